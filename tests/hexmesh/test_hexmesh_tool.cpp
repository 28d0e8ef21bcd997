// The latmpm-hexmesh program end to end: a paper-B cylinder, its .msh read back, exit statuses.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sys/wait.h>
#include <unistd.h>

#include "core/hdf5_file.hpp"
#include "core/provenance.hpp"
#include "points/point_set.hpp"
#include "scratch_dir.hpp"

using namespace latmpm;
namespace fs = std::filesystem;

namespace {

struct ToolScratch : test::ScratchDir {
  ToolScratch() : test::ScratchDir("hexmesh-tool"), dir(path()) {}
  fs::path dir;
  int run(const std::string& args) const {
    const std::string line = "cd '" + dir.string() + "' && '" + std::string(LATMPM_BIN_DIR) +
                             "/latmpm-hexmesh' " + args + " 2> stderr.txt";
    const int status = std::system(line.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  std::string stderr_text() const {
    std::ifstream in(dir / "stderr.txt");
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  }
};

}  // namespace

TEST_CASE("latmpm-hexmesh writes paper B's B2 cylinder as CPDI points and reads its own mesh back",
          "[hexmesh][tool]") {
  ToolScratch s;
  REQUIRE(s.run("--cylinder --diameter 4mm --height 4mm --level 2 --cell 0.4mm --msh b2.msh -o b2.h5 --quiet") == 0);
  const Hdf5File f(s / "b2.h5", Hdf5File::Mode::read);
  const PointSet p = read_point_set(f);
  CHECK(p.size() == 384);
  CHECK(p.domain_vertices.size() == 384);
  CHECK(p.cell_size == Approx(0.4e-3));
  double volume = 0;
  for (double v : p.volume) volume += v;
  const int sides = 16;
  CHECK(volume == Approx(4e-3 * sides / 2.0 * 4e-6 * std::sin(2 * M_PI / sides)).epsilon(1e-12));
  CHECK(read_provenance(f).tool == "latmpm-hexmesh");
  CHECK(fs::exists(s / "b2.xmf"));
  REQUIRE(s.run("b2.msh --units m --cell 0.4mm -o read.h5 --quiet") == 0);
  CHECK(read_point_set(Hdf5File(s / "read.h5", Hdf5File::Mode::read)).size() == 384);
}

TEST_CASE("latmpm-hexmesh refuses bad input with status 2 and one line, leaving no output", "[hexmesh][tool]") {
  ToolScratch s;
  // A missing required option is a usage error (1), as for every tool (docs/robustness.md).
  CHECK(s.run("--cylinder --diameter 4mm --height 4mm --cell 0.4mm -o x.h5") == 1);
  CHECK(s.stderr_text().find("--level") != std::string::npos);
  CHECK(s.run("--cylinder --diameter -4mm --height 4mm --level 1 --cell 0.4mm -o x.h5") == 2);
  CHECK(s.stderr_text().find("--diameter") != std::string::npos);
  CHECK(s.run("--cylinder --diameter 4mm --height 4mm --level 13 --cell 0.4mm -o x.h5") == 2);
  CHECK(s.stderr_text().find("--level") != std::string::npos);
  CHECK(s.run("missing.msh --units mm --cell 0.4mm -o x.h5") == 2);
  CHECK(s.stderr_text().find("missing.msh") != std::string::npos);
  CHECK(s.run("--cylinder --diameter 4mm --height 4mm --divisions 2,x,3 --cell 0.4mm -o x.h5") == 2);
  CHECK_FALSE(fs::exists(s / "x.h5"));
  CHECK(s.run("--no-such-option") == 1);
}
