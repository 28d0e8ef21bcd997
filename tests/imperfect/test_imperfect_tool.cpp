// The latmpm-imperfect program end to end: files and pipes, provenance, exit statuses.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sys/wait.h>
#include <unistd.h>

#include "core/hdf5_file.hpp"
#include "core/provenance.hpp"
#include "geometry/lattice.hpp"
#include "synthetic_inputs.hpp"
#include "scratch_dir.hpp"

using namespace latmpm;
namespace fs = std::filesystem;

namespace {

struct Scratch : test::ScratchDir {
  Scratch() : test::ScratchDir("imperfect-tool"), dir(path()) {}
  fs::path dir;
};

// Runs a shell command line in the scratch directory with the tool on PATH; returns the
// exit status and the lines written to stderr.
std::pair<int, std::vector<std::string>> shell(const Scratch& scratch, const std::string& command) {
  const std::string err = scratch / "stderr.txt";
  const std::string line = "cd '" + scratch.dir.string() + "' && PATH='" + std::string(LATMPM_BIN_DIR) +
                           "':\"$PATH\" bash -o pipefail -c '" + command + "' 2> '" + err + "'";
  const int status = std::system(line.c_str());
  std::vector<std::string> lines;
  std::ifstream in(err);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, lines};
}

void write_points(const std::string& path, const PointSet& points) {
  Hdf5File f(path, Hdf5File::Mode::create);
  const char* argv[] = {"latmpm-voxelize", "block.h5", "--cell", "0.64mm"};
  Provenance p = Provenance::for_run("latmpm-voxelize", 4, argv);
  write_point_set(f, points);
  write_provenance(f, p);
}

}  // namespace

TEST_CASE("latmpm-imperfect perturbs a point-set file and through pipes, recording each step in order",
          "[imperfect][tool]") {
  Scratch scratch;
  const PointSet start = test::printed_block();
  write_points(scratch / "block.h5", start);
  auto [status, err] = shell(scratch, "cat block.h5 | latmpm-imperfect - --type C -o - --quiet | "
                                      "latmpm-imperfect - --type D --direction y --amount 1mm -o out.h5 --quiet");
  REQUIRE(status == 0);
  CHECK(err.empty());
  Hdf5File out(scratch / "out.h5", Hdf5File::Mode::read);
  const PointSet result = read_point_set(out);
  REQUIRE(result.size() == start.size());
  CHECK(result.volume == start.volume);
  const auto records = out.read_strings("/imperfections");
  REQUIRE(records.size() == 2);
  CHECK_THAT(records[0], Catch::StartsWith("C curved-top-base"));
  CHECK_THAT(records[1], Catch::StartsWith("D bowed-lattice"));
  // History: the voxelizer's run, the first imperfect run and its step, then this run's step.
  const Provenance p = read_provenance(out);
  CHECK(p.tool == "latmpm-imperfect");
  REQUIRE(p.history.size() == 4);
  CHECK_THAT(p.history[0], Catch::Contains("latmpm-voxelize"));
  CHECK_THAT(p.history[1], Catch::Contains("latmpm-imperfect") && Catch::Contains("C curved-top-base"));
  CHECK_THAT(p.history[2], Catch::Contains("latmpm-imperfect - --type C"));
  CHECK_THAT(p.history[3], Catch::Contains("D bowed-lattice"));
}

TEST_CASE("latmpm-imperfect refuses bad input with exit status 2, one line and no file", "[imperfect][tool]") {
  Scratch scratch;
  write_points(scratch / "block.h5", test::printed_block());
  const auto [args, named] = GENERATE(table<std::string, std::string>({
      {"--type E", "--type"},
      {"--type C --amount 1.28", "--amount"},
      {"--type B --bodies lattice,lid", "--bodies"},
      {"--type A --amount 12mm", "--amount"},
      {"--type D --direction z", "--direction"},
      {"--waviness 1%", "--waviness"},
  }));
  const auto [status, err] = shell(scratch, "latmpm-imperfect block.h5 " + args + " -o out.h5");
  CHECK(status == 2);
  REQUIRE(err.size() == 1);
  CHECK_THAT(err[0], Catch::StartsWith("latmpm-imperfect: " + named));
  CHECK_FALSE(fs::exists(scratch / "out.h5"));
  const auto [missing, missing_err] = shell(scratch, "latmpm-imperfect nothing.h5 --type A -o out.h5");
  CHECK(missing == 2);
  CHECK(missing_err.size() == 1);
}

TEST_CASE("latmpm-imperfect gives a strut graph the same defects for the same seed", "[imperfect][tool]") {
  Scratch scratch;
  {
    Hdf5File f(scratch / "t1p40.h5", Hdf5File::Mode::create);
    write_strut_graph(f, build_lattice(preset_lattice("T1P40")));
  }
  const std::string run = "latmpm-imperfect t1p40.h5 --waviness 1% --strut-diameter-cov 5% --missing-struts 1% "
                          "--disconnected drop --quiet --seed 4 -o ";
  REQUIRE(shell(scratch, run + "a.h5").first == 0);
  REQUIRE(shell(scratch, run + "b.h5").first == 0);
  Hdf5File a(scratch / "a.h5", Hdf5File::Mode::read), b(scratch / "b.h5", Hdf5File::Mode::read);
  CHECK(a.read_doubles("/geometry/nodes") == b.read_doubles("/geometry/nodes"));
  CHECK(a.read_doubles("/geometry/strut_radius") == b.read_doubles("/geometry/strut_radius"));
  CHECK(a.read_int32("/geometry/strut_member") == b.read_int32("/geometry/strut_member"));
  CHECK(a.read_strings("/imperfections").size() == 3);
}
