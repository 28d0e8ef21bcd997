// latmpm-voxelize as a program: every bad input exits with status 2 (1 for a malformed
// command line) and leaves no output file behind; a good run writes the point set and its
// XDMF view.
#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "core/hdf5_file.hpp"
#include "mesh/primitive_meshes.hpp"
#include "mesh/stl_file.hpp"
#include "points/point_set.hpp"
#include "scratch_dir.hpp"

using namespace latmpm;

namespace {

const std::string dir = test::process_scratch("voxelize-tool").string();

bool exists(const std::string& path) { return std::ifstream(path).good(); }

int run(const std::string& arguments) {
  const std::string command = std::string(LATMPM_BIN_DIR) + "/latmpm-voxelize " + arguments + " 2>" + dir + "/stderr.txt";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

}  // namespace

TEST_CASE("latmpm-voxelize refuses bad input with status 2 and writes nothing", "[voxelize]") {
  REQUIRE(std::system(("mkdir -p " + dir).c_str()) == 0);
  const std::string good = dir + "/good.stl", out = dir + "/out.h5";
  write_stl(box_mesh({0, 0, 0}, {0.004, 0.004, 0.004}), good, 1e-3);
  std::ifstream in(good, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  write_bytes(dir + "/empty.stl", "");
  write_bytes(dir + "/truncated.stl", bytes.substr(0, bytes.size() - 20));
  std::string nan_bytes = bytes;
  nan_bytes.replace(84 + 12, 4, "\xff\xff\xff\x7f", 4);  // a NaN x in triangle 0
  write_bytes(dir + "/nan.stl", nan_bytes);
  write_bytes(dir + "/inf.stl", "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 inf\nvertex 1 0 0\n"
                                "vertex 0 1 0\nendloop\nendfacet\nendsolid s\n");
  // A closed but flat "pillow": two triangles back to back enclose no volume.
  write_bytes(dir + "/flat.stl", "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                                 "vertex 0 1 0\nendloop\nendfacet\nfacet normal 0 0 -1\nouter loop\n"
                                 "vertex 0 0 0\nvertex 0 1 0\nvertex 1 0 0\nendloop\nendfacet\nendsolid s\n");
  TriangleMesh holed = box_mesh({0, 0, 0}, {0.004, 0.004, 0.004});
  holed.triangles.pop_back();
  write_stl(holed, dir + "/hole.stl", 1e-3);

  struct Case { const char* what; std::string arguments; int status; };
  const Case c = GENERATE_COPY(
      Case{"empty STL", dir + "/empty.stl --units mm --cell 1mm", 2},
      Case{"truncated STL", dir + "/truncated.stl --units mm --cell 1mm", 2},
      Case{"NaN coordinate", dir + "/nan.stl --units mm --cell 1mm", 2},
      Case{"Inf coordinate", dir + "/inf.stl --units mm --cell 1mm", 2},
      Case{"zero-volume solid", dir + "/flat.stl --units mm --cell 1mm", 2},
      Case{"mesh with a hole", dir + "/hole.stl --units mm --cell 1mm", 2},
      Case{"cell zero", good + " --units mm --cell 0mm", 2},
      Case{"cell negative", good + " --units mm --cell -1mm", 2},
      Case{"ppc zero", good + " --units mm --cell 1mm --ppc 0", 2},
      Case{"cell without unit", good + " --units mm --cell 0.64", 2},
      Case{"STL without --units", good + " --cell 1mm", 2},
      Case{"missing input file", dir + "/none.stl --units mm --cell 1mm", 2},
      Case{"unknown option", good + " --units mm --cell 1mm --cel 2mm", 1});
  SECTION(c.what) {
    std::remove(out.c_str());
    CHECK(run(c.arguments + " --quiet -o " + out) == c.status);
    CHECK_FALSE(exists(out));
    CHECK_FALSE(exists(dir + "/out.xmf"));
    std::ifstream err(dir + "/stderr.txt");
    std::string line, last;
    int lines = 0;
    while (std::getline(err, line)) {
      last = line;
      ++lines;
    }
    INFO(last);
    CHECK(lines == 1);  // one clear line, nothing else (--quiet: no summary)
    CHECK(last.rfind("latmpm-voxelize: ", 0) == 0);
  }
}

TEST_CASE("latmpm-voxelize writes the point set and an XDMF file beside it", "[voxelize]") {
  REQUIRE(std::system(("mkdir -p " + dir).c_str()) == 0);
  const std::string stl = dir + "/part.stl", out = dir + "/part-points.h5";
  write_stl(cylinder_mesh({0, 0, 0}, 0.003, 0.006, 48), stl, 1e-3);
  REQUIRE(run(stl + " --units mm --cell 1mm --ppc 2 --body sample --quiet -o " + out) == 0);
  const PointSet p = read_point_set(Hdf5File(out, Hdf5File::Mode::read));
  CHECK(p.body_names == std::vector<std::string>{"sample"});
  CHECK(p.cell_size == Approx(0.001));
  CHECK(p.ppc == 2);
  CHECK(p.tags.count("record") == 1);
  std::ifstream xmf(dir + "/part-points.xmf");
  const std::string text((std::istreambuf_iterator<char>(xmf)), std::istreambuf_iterator<char>());
  CHECK(text.find("NumberOfElements=\"" + std::to_string(p.size()) + "\"") != std::string::npos);
  CHECK(text.find("part-points.h5:/points/position") != std::string::npos);
  CHECK(text.find("part-points.h5:/points/tags/record") != std::string::npos);
}
