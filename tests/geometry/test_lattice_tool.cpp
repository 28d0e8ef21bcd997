// latmpm-lattice as a program: bad input gives one line naming the option and leaves no
// file behind; a good run writes a strut graph with provenance, also through stdout.
#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "core/hdf5_file.hpp"
#include "core/provenance.hpp"
#include "geometry/strut_graph.hpp"
#include "scratch_dir.hpp"

using namespace latmpm;
namespace fs = std::filesystem;

namespace {

struct Run {
  int status;
  std::string err;
};

// Runs latmpm-lattice in `dir` with `args`, stdout to `dir`/stdout, stderr captured.
Run run_tool(const fs::path& dir, const std::string& args) {
  const std::string command = "cd '" + dir.string() + "' && '" + std::string(LATMPM_BIN_DIR) +
                              "/latmpm-lattice' " + args + " > stdout 2> stderr";
  const int raw = std::system(command.c_str());
  std::ifstream err(dir / "stderr");
  Run run{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1,
          std::string(std::istreambuf_iterator<char>(err), std::istreambuf_iterator<char>())};
  fs::remove(dir / "stdout");
  fs::remove(dir / "stderr");
  return run;
}

fs::path scratch(const std::string& name) {
  const fs::path dir = test::process_scratch("lattice-tool").path() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

}  // namespace

TEST_CASE("Bad input exits 2 with one line naming the option and leaves no file", "[geometry][tool]") {
  auto [args, option] = GENERATE(table<std::string, std::string>({
      {"--preset T2P30 --strut-length 0mm", "--strut-length"},
      {"--preset T2P30 --strut-diameter -2mm", "--strut-diameter"},
      {"--preset T2P30 --angle 90deg", "--angle"},
      {"--preset T2P30 --angle 0deg", "--angle"},
      {"--preset T2P30 --cells 5x0x5", "--cells"},
      {"--preset T2P30 --cells 5x5", "--cells"},
      {"--preset T4P30", "--preset"},
      {"--preset T2P30 --strut-length 8", "--strut-length"},  // no unit
      {"--preset T2P30 --angle 30", "--angle"},                // no unit
      {"--preset T2P30 --plates 0mm", "--plates"},
      {"--cell kelvin --strut-length 5mm --strut-diameter 1mm", "--cell"},
      {"--column --diameter 2.4mm --length -16mm", "--length"},
      {"--preset T2P30 --stl missing-dir/x.stl", "--stl"},
      {"--preset T2P30 -o missing-dir/x.h5", "--output"},
      {"--preset T2P30 --voxel 0mm", "--voxel"},
      {"--preset T2P30 --voxel 1um", "--voxel"},  // 68 000 voxels across: refused, not attempted
  }));
  CAPTURE(args);
  const fs::path dir = scratch("bad");
  // Outputs are claimed as a normal run would (unless the case is about them).
  std::string full = args;
  if (args.find("-o ") == std::string::npos) full += " -o out.h5";
  if (args.find("--stl ") == std::string::npos) full += " --stl out.stl";
  const Run run = run_tool(dir, full);
  CHECK(run.status == 2);
  CHECK(run.err.find(option + ":") != std::string::npos);
  CHECK(std::count(run.err.begin(), run.err.end(), '\n') == 1);
  CHECK(fs::is_empty(dir));
  fs::remove_all(dir);
}

TEST_CASE("A run writes the strut graph with provenance, to a file or to stdout", "[geometry][tool]") {
  const fs::path dir = scratch("good");
  const bool to_stdout = GENERATE(false, true);
  const std::string args = "--preset T1P30 --cells 2x2x2 --quiet " + std::string(to_stdout ? "-o - > " : "-o ") + "out.h5";
  const std::string command = "cd '" + dir.string() + "' && '" + std::string(LATMPM_BIN_DIR) + "/latmpm-lattice' " + args;
  REQUIRE(std::system(command.c_str()) == 0);
  {
    Hdf5File file((dir / "out.h5").string(), Hdf5File::Mode::read);
    const StrutGraph g = read_strut_graph(file);
    CHECK(g.name == "T1P30");
    CHECK(g.struts.size() == 4 * 2 * 2 * 2);
    CHECK(g.plates.size() == 2);
    CHECK(g.parameters.at("cell") == "tetrahedral");
    const Provenance p = read_provenance(file);
    CHECK(p.tool == "latmpm-lattice");
    CHECK(p.command_line.find("--preset T1P30") != std::string::npos);
  }
  fs::remove_all(dir);
}
