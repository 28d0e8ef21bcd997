// A part clipped at its bounding box (a lattice cut out of a larger one) has openings on the
// box's faces; --repair closes them with the planar region on that face, so the volume is the
// clipped solid's exactly. Meshes that are no solid (an open sheet, a triangle soup) need far
// more invented surface than a few missing faces, which the repair report shows.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "mesh/mesh_checks.hpp"
#include "mesh/mesh_repair.hpp"
#include "mesh/primitive_meshes.hpp"

using namespace latmpm;

namespace {

// A prism over a polygon with holes: `rings` (counter-clockwise outer, clockwise holes, in
// x–y) extruded from z = 0 to `height`, side walls only: both ends open, as if clipped.
TriangleMesh open_prism(const std::vector<std::vector<Eigen::Vector2d>>& rings, double height) {
  TriangleMesh m;
  for (const auto& ring : rings) {
    const auto base = static_cast<int32_t>(m.vertices.size());
    const auto n = static_cast<int32_t>(ring.size());
    for (int level = 0; level < 2; ++level)
      for (const auto& p : ring) m.vertices.emplace_back(p.x(), p.y(), level * height);
    for (int32_t i = 0; i < n; ++i) {
      const int32_t j = (i + 1) % n;
      m.triangles.push_back({base + i, base + j, base + n + j});  // outward for a ccw ring
      m.triangles.push_back({base + i, base + n + j, base + n + i});
    }
  }
  return m;
}

std::vector<Eigen::Vector2d> square(double lo, double hi, bool clockwise) {
  std::vector<Eigen::Vector2d> r{{lo, lo}, {hi, lo}, {hi, hi}, {lo, hi}};
  if (clockwise) std::reverse(r.begin(), r.end());
  return r;
}

}  // namespace

TEST_CASE("Repair caps a clipped square tube with rings, keeping its bore open", "[mesh]") {
  // Outer 10 x 10, bore 4 x 4, 10 long: 840 exactly. Filling each loop separately would
  // close the bore as well (or overlap the caps).
  TriangleMesh tube = open_prism({square(0, 10, false), square(3, 7, true)}, 10);
  REQUIRE(check_mesh(tube).boundary_edges == 16);
  const RepairReport rep = repair_mesh(tube);
  CHECK(rep.loops_capped == 4);
  CHECK(rep.holes_filled == 0);
  CHECK(rep.filled_area == 0);
  CHECK(rep.cap_area == Approx(2 * 84.0));
  const MeshReport r = check_mesh(tube);
  CHECK(r.closed());
  CHECK(r.is_valid_solid());
  CHECK(r.volume == Approx(840.0).epsilon(1e-12));
}

TEST_CASE("Repair caps a non-convex clipped strut (a plus-shaped prism) exactly", "[mesh]") {
  // A plus sign of arms 1 wide, 3 across: area 5, 2 long: volume 10.
  const std::vector<Eigen::Vector2d> plus{{1, 0}, {2, 0}, {2, 1}, {3, 1}, {3, 2}, {2, 2},
                                          {2, 3}, {1, 3}, {1, 2}, {0, 2}, {0, 1}, {1, 1}};
  TriangleMesh prism = open_prism({plus}, 2);
  const RepairReport rep = repair_mesh(prism);
  CHECK(rep.loops_capped == 2);
  const MeshReport r = check_mesh(prism);
  CHECK(r.is_valid_solid());
  CHECK(r.volume == Approx(10.0).epsilon(1e-12));
}

TEST_CASE("Repair caps the sliced end of a strut on its box face, and the other end too", "[mesh]") {
  TriangleMesh can = cylinder_mesh({0, 0, 0}, 1.0, 2.0, 64);
  const double exact = check_mesh(can).volume;  // the 64-gon prism
  can.triangles.erase(std::remove_if(can.triangles.begin(), can.triangles.end(),
                                     [](const auto& t) { return t[0] == 2 * 64 || t[0] == 2 * 64 + 1; }),
                      can.triangles.end());
  const RepairReport rep = repair_mesh(can);
  CHECK(rep.loops_capped == 2);
  CHECK(rep.filled_area == 0);
  const MeshReport r = check_mesh(can);
  CHECK(r.is_valid_solid());
  CHECK(r.volume == Approx(exact).epsilon(1e-12));
}

TEST_CASE("An open wavy sheet and a triangle soup need most of their surface invented", "[mesh]") {
  TriangleMesh sheet;
  const int n = 20;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      sheet.vertices.emplace_back(i, j, 0.5 * std::sin(0.7 * i) * std::cos(0.5 * j));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      sheet.triangles.push_back({a, b, d});
      sheet.triangles.push_back({a, d, c});
    }
  TriangleMesh soup;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(0, 10);
  for (int t = 0; t < 50; ++t) {
    for (int k = 0; k < 3; ++k) soup.vertices.emplace_back(coordinate(random), coordinate(random), coordinate(random));
    soup.triangles.push_back({3 * t, 3 * t + 1, 3 * t + 2});
  }
  for (TriangleMesh* mesh : {&sheet, &soup}) {
    const RepairReport rep = repair_mesh(*mesh);
    INFO(rep.filled_area << " of " << rep.surface_area);
    CHECK(rep.filled_area > 0.3 * rep.surface_area);
    CHECK(rep.filled_area > max_filled_area_fraction * rep.surface_area);
  }
}
