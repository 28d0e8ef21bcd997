// Near-coincident vertices, as CAD exports write them (each facet with its own rounding
// noise on shared corners), are welded so that a closed solid is seen as closed.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <map>

#include "mesh/mesh_checks.hpp"
#include "mesh/primitive_meshes.hpp"
#include "mesh/vertex_weld.hpp"

using namespace latmpm;

namespace {

// A CAD-like cube: every face split into n x n squares, every triangle with its own three
// vertices, and every coordinate that should be 0 written as ±3e-16 (the sign alternating
// per triangle), as a CAD kernel's transformed vertices come out.
TriangleMesh cad_like_cube(double size, int n) {
  const TriangleMesh box = box_mesh({0, 0, 0}, {size, size, size});
  TriangleMesh soup;
  int parity = 0;
  for (const auto& t : box.triangles) {
    // Subdivide the triangle (a half of a face) into n² triangles, barycentric grid.
    const Eigen::Vector3d a = box.vertices[t[0]], b = box.vertices[t[1]], c = box.vertices[t[2]];
    auto at = [&](int i, int j) { return a + (b - a) * double(i) / n + (c - a) * double(j) / n; };
    auto add = [&](const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Eigen::Vector3d& r) {
      const double noise = (parity++ % 2 ? 3e-16 : -3e-16);
      for (Eigen::Vector3d v : {p, q, r}) {
        for (int axis = 0; axis < 3; ++axis)
          if (v[axis] == 0) v[axis] = noise;
        soup.vertices.push_back(v);
      }
      const auto k = static_cast<int32_t>(soup.vertices.size());
      soup.triangles.push_back({k - 3, k - 2, k - 1});
    };
    for (int i = 0; i < n; ++i)
      for (int j = 0; i + j < n; ++j) {
        add(at(i, j), at(i + 1, j), at(i, j + 1));
        if (i + j + 1 < n) add(at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
      }
  }
  return soup;
}

// What read_stl does: vertices with identical coordinates become one.
void merge_identical(TriangleMesh& mesh) {
  std::map<std::array<double, 3>, int32_t> index;
  std::vector<Eigen::Vector3d> kept;
  for (auto& t : mesh.triangles)
    for (auto& i : t) {
      const Eigen::Vector3d v = mesh.vertices[i];
      auto [it, inserted] = index.emplace(std::array<double, 3>{v.x(), v.y(), v.z()}, int32_t(kept.size()));
      if (inserted) kept.push_back(v);
      i = it->second;
    }
  mesh.vertices.swap(kept);
}

}  // namespace

TEST_CASE("Welding near-coincident vertices closes a CAD-like cube exactly", "[mesh]") {
  TriangleMesh noisy = cad_like_cube(0.01, 4);
  // Exact merging joins only bit-identical corners: the ±3e-16 ones stay apart, the cube is open.
  merge_identical(noisy);
  const MeshReport before = check_mesh(noisy, false);
  CHECK_FALSE(before.closed());
  CHECK(before.boundary_edges > 0);
  const WeldReport report = weld_nearby_vertices(noisy);
  CHECK(report.vertices_welded > 0);
  CHECK(report.largest_gap == Approx(6e-16 * std::sqrt(3.0)).margin(1e-15));
  CHECK(report.tolerance == Approx(1e-6 * 0.01 * std::sqrt(3.0)));
  const MeshReport r = check_mesh(noisy);
  CHECK(r.closed());
  CHECK(r.is_valid_solid());
  CHECK(r.shells == 1);
  CHECK(r.volume == Approx(1e-6).epsilon(1e-12));
  CHECK_FALSE(describe(report).empty());
}

TEST_CASE("Welding leaves vertices farther apart than the tolerance alone", "[mesh]") {
  // Two boxes 1e-5 of their size apart: a real gap, not noise.
  TriangleMesh two = box_mesh({0, 0, 0}, {1, 1, 1});
  append(two, box_mesh({1 + 1e-5, 0, 0}, {2, 1, 1}));
  const size_t vertices = two.vertices.size();
  const WeldReport report = weld_nearby_vertices(two);
  CHECK(report.vertices_welded == 0);
  CHECK(two.vertices.size() == vertices);
  CHECK(check_mesh(two).shells == 2);
}
