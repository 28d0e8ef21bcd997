// STL reading and writing: round trips, encoding detection by size, and every bad input
// giving an InputError that names the file and the problem.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

#include "core/errors.hpp"
#include "mesh/mesh_checks.hpp"
#include "mesh/primitive_meshes.hpp"
#include "mesh/stl_file.hpp"
#include "scratch_dir.hpp"

using namespace latmpm;

namespace {

std::string scratch_path(const std::string& name) { return test::process_scratch("mesh") / name; }

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void spit(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

}  // namespace

TEST_CASE("A mesh written as STL reads back with the same vertices and triangles", "[mesh]") {
  const StlEncoding encoding = GENERATE(StlEncoding::binary, StlEncoding::ascii);
  const TriangleMesh original = sphere_mesh({0.01, -0.02, 0.005}, 0.004, 2);
  const std::string path = scratch_path("roundtrip.stl");
  write_stl(original, path, 1e-3, encoding);
  StlEncoding detected{};
  const TriangleMesh back = read_stl(path, 1e-3, &detected);
  CHECK(detected == encoding);
  // STL repeats each vertex per triangle: welding must recover the shared vertices exactly.
  REQUIRE(back.vertices.size() == original.vertices.size());
  REQUIRE(back.triangles.size() == original.triangles.size());
  for (size_t t = 0; t < original.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d a = original.vertices[original.triangles[t][k]];
      const Eigen::Vector3d b = back.vertices[back.triangles[t][k]];
      // STL holds single precision: each coordinate within half a float ulp (2^-24 relative).
      for (int i = 0; i < 3; ++i) CHECK(std::fabs(a[i] - b[i]) <= std::fabs(a[i]) * 0x1p-24 * (1 + 1e-9));
    }
  CHECK(check_mesh(back).is_valid_solid());
  std::remove(path.c_str());
}

TEST_CASE("Binary and ASCII STL of one mesh read back bit-identical", "[mesh]") {
  const TriangleMesh original = sphere_mesh({0.001, 0.002, 0.003}, 0.0123456789, 3);
  const std::string bin = scratch_path("same.bin.stl"), txt = scratch_path("same.txt.stl");
  write_stl(original, bin, 1e-3, StlEncoding::binary);
  write_stl(original, txt, 1e-3, StlEncoding::ascii);
  const TriangleMesh a = read_stl(bin, 1e-3), b = read_stl(txt, 1e-3);
  REQUIRE(a.vertices.size() == b.vertices.size());
  CHECK(a.triangles == b.triangles);
  for (size_t v = 0; v < a.vertices.size(); ++v) CHECK(a.vertices[v] == b.vertices[v]);
  std::remove(bin.c_str());
  std::remove(txt.c_str());
}

TEST_CASE("The unit of an STL file scales its coordinates to metres", "[mesh]") {
  const TriangleMesh box = box_mesh({0, 0, 0}, {0.002, 0.003, 0.004});  // 2 × 3 × 4 mm
  const std::string path = scratch_path("units.stl");
  write_stl(box, path, 1e-3);
  CHECK(check_mesh(read_stl(path, 1e-3)).volume == Approx(24e-9).epsilon(1e-6));
  // The same file read as inches: every length 25.4 / 1 times larger than in millimetres.
  CHECK(check_mesh(read_stl(path, 0.0254)).volume == Approx(24.0 * std::pow(0.0254, 3)).epsilon(1e-6));
  std::remove(path.c_str());
}

TEST_CASE("A binary STL whose header starts with 'solid' is read as binary", "[mesh]") {
  const TriangleMesh box = box_mesh({0, 0, 0}, {0.001, 0.001, 0.001});
  const std::string path = scratch_path("solid-header.stl");
  write_stl(box, path, 1e-3, StlEncoding::binary);
  std::string bytes = slurp(path);
  std::memcpy(&bytes[0], "solid exported by some CAD", 26);
  spit(path, bytes);
  StlEncoding detected{};
  const TriangleMesh back = read_stl(path, 1e-3, &detected);
  CHECK(detected == StlEncoding::binary);
  CHECK(back.triangles.size() == 12);
  CHECK(back.vertices.size() == 8);
  std::remove(path.c_str());
}

TEST_CASE("ASCII STL with several solids, polygons and odd spacing is read", "[mesh]") {
  const std::string path = scratch_path("quirky.stl");
  spit(path,
       "solid first part\r\n facet normal 0 0 0\n outer loop\n vertex 0 0 0\n vertex +1e0 0 0\n"
       "  vertex 1 1 0\n vertex 0 1 0\n endloop\n endfacet\nendsolid first part\n"
       "solid second\nfacet normal 0 0 1 outer loop vertex 0 0 1 vertex 1 0 1 vertex 1 1 1 "
       "endloop endfacet endsolid\n");
  const TriangleMesh m = read_stl(path, 1.0);
  CHECK(m.triangles.size() == 3);  // the quad fans into two triangles
  CHECK(m.vertices.size() == 7);
  std::remove(path.c_str());
}

TEST_CASE("Bad STL files give an InputError naming the file and the problem", "[mesh]") {
  const TriangleMesh box = box_mesh({0, 0, 0}, {0.001, 0.001, 0.001});
  const std::string bin = scratch_path("good.bin.stl"), txt = scratch_path("good.txt.stl");
  write_stl(box, bin, 1e-3, StlEncoding::binary);
  write_stl(box, txt, 1e-3, StlEncoding::ascii);
  const std::string good_bin = slurp(bin), good_txt = slurp(txt);

  struct Case { const char* what; std::string bytes; const char* expected; };
  std::string nan_bin = good_bin;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(&nan_bin[84 + 50 * 5 + 12 + 4], &nan, 4);  // triangle 5, vertex 1, y
  std::string inf_txt = good_txt;
  inf_txt.replace(inf_txt.find("vertex ") + 7, 1, "inf");
  std::string huge_txt = good_txt, beyond_float_txt = good_txt;
  huge_txt.replace(huge_txt.find("vertex ") + 7, 1, "1e999");  // from_chars: out of range, value left 0
  beyond_float_txt.replace(beyond_float_txt.find("vertex ") + 7, 1, "-1e39");
  std::string zero_bin(84, '\0');
  const Case c = GENERATE_COPY(
      Case{"empty", "", "empty file"},
      Case{"truncated binary", good_bin.substr(0, good_bin.size() - 7), "truncated"},
      Case{"truncated ASCII", good_txt.substr(0, good_txt.size() / 2), "line"},
      Case{"NaN in binary", nan_bin, "triangle 5"},
      Case{"Inf in ASCII", inf_txt, "triangle 0"},
      Case{"1e999 in ASCII", huge_txt, "'1e999' is out of range"},
      Case{"-1e39 in ASCII", beyond_float_txt, "beyond single precision"},
      Case{"no triangles", zero_bin, "no triangles"},
      Case{"too short", "abc", "too short"},
      Case{"ASCII garbage", "solid x\n facet normal 0 0 1\n outer loop\n vertex 1 2 x\n", "expected a number"});
  SECTION(c.what) {
    const std::string path = scratch_path("bad.stl");
    spit(path, c.bytes);
    try {
      read_stl(path, 1e-3);
      FAIL("no error for " << c.what);
    } catch (const InputError& e) {
      INFO(e.what());
      CHECK(e.where() == path);
      CHECK(std::string(e.what()).find(c.expected) != std::string::npos);
    }
    std::remove(path.c_str());
  }
  std::remove(bin.c_str());
  std::remove(txt.c_str());
}

TEST_CASE("A missing STL file is an InputError", "[mesh]") {
  CHECK_THROWS_AS(read_stl("/nonexistent/part.stl", 1e-3), InputError);
}
