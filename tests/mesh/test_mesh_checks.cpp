// Mesh checks against meshes with known, deliberately introduced defects, and volumes
// against exact formulas.
#include <catch2/catch.hpp>

#include <cmath>

#include "mesh/mesh_checks.hpp"
#include "mesh/primitive_meshes.hpp"

using namespace latmpm;

TEST_CASE("Closed primitive meshes are valid solids with their exact volumes", "[mesh]") {
  SECTION("box") {
    const MeshReport r = check_mesh(box_mesh({0.1, -0.2, 0.3}, {0.13, -0.15, 0.37}));
    CHECK(r.is_valid_solid());
    CHECK(r.volume == Approx(0.03 * 0.05 * 0.07).epsilon(1e-12));
  }
  SECTION("cylinder: the polygon prism volume (n/2) r² sin(2π/n) h") {
    const int n = GENERATE(3, 7, 64);
    const MeshReport r = check_mesh(cylinder_mesh({1, 2, 3}, 0.5, 2.0, n));
    CHECK(r.is_valid_solid());
    CHECK(r.volume == Approx(n / 2.0 * 0.25 * std::sin(2 * M_PI / n) * 2.0).epsilon(1e-12));
  }
  SECTION("icosphere: volume converges to (4/3)πr³ from below") {
    const double exact = 4.0 / 3.0 * M_PI;
    double previous = 0;
    for (int s = 0; s <= 4; ++s) {
      const MeshReport r = check_mesh(sphere_mesh({0, 0, 0}, 1.0, s), s <= 2);
      CHECK(r.closed());
      CHECK(r.consistently_oriented);
      CHECK(r.outward);
      CHECK(r.volume < exact);
      CHECK(r.volume > previous);
      previous = r.volume;
    }
    CHECK(previous == Approx(exact).epsilon(0.005));
  }
}

TEST_CASE("A hole in a box leaves boundary edges and the box is no longer closed", "[mesh]") {
  TriangleMesh box = box_mesh({0, 0, 0}, {1, 1, 1});
  box.triangles.pop_back();
  const MeshReport r = check_mesh(box);
  CHECK(r.boundary_edges == 3);
  CHECK_FALSE(r.closed());
  CHECK_FALSE(r.encloses_volume());
  CHECK_FALSE(r.is_valid_solid());
}

TEST_CASE("One flipped triangle breaks consistent orientation", "[mesh]") {
  TriangleMesh box = box_mesh({0, 0, 0}, {1, 1, 1});
  std::swap(box.triangles[4][0], box.triangles[4][1]);
  const MeshReport r = check_mesh(box);
  CHECK(r.closed());
  CHECK_FALSE(r.consistently_oriented);
  CHECK_FALSE(r.is_valid_solid());
}

TEST_CASE("An inside-out mesh is closed and consistent but not outward", "[mesh]") {
  TriangleMesh sphere = sphere_mesh({0, 0, 0}, 2.0, 1);
  const double outward_volume = check_mesh(sphere).volume;
  for (auto& t : sphere.triangles) std::swap(t[1], t[2]);
  const MeshReport r = check_mesh(sphere);
  CHECK(r.encloses_volume());
  CHECK_FALSE(r.outward);
  CHECK(r.volume == Approx(outward_volume));
  CHECK(signed_volume(sphere) == Approx(-outward_volume));
}

TEST_CASE("Duplicate and degenerate faces are counted", "[mesh]") {
  TriangleMesh box = box_mesh({0, 0, 0}, {1, 1, 1});
  box.triangles.push_back(box.triangles[0]);                                  // duplicate
  box.triangles.push_back({box.triangles[3][2], box.triangles[3][1], box.triangles[3][0]});  // reversed copy
  box.vertices.emplace_back(0.5, 0, 0);  // on the edge 0–1
  const auto mid = static_cast<int32_t>(box.vertices.size() - 1);
  box.triangles.push_back({0, mid, 1});  // collinear corners
  box.triangles.push_back({2, 2, 3});    // repeated vertex
  const MeshReport r = check_mesh(box);
  CHECK(r.duplicate_faces == 2);
  CHECK(r.degenerate_faces == 2);
  CHECK(r.non_manifold_edges > 0);  // the copies put a third and fourth face on their edges
  CHECK_FALSE(r.is_valid_solid());
}

TEST_CASE("A fin on an edge makes that edge non-manifold", "[mesh]") {
  TriangleMesh box = box_mesh({0, 0, 0}, {1, 1, 1});
  box.vertices.emplace_back(0.5, -1, -1);
  box.triangles.push_back({0, 1, static_cast<int32_t>(box.vertices.size() - 1)});
  const MeshReport r = check_mesh(box);
  CHECK(r.non_manifold_edges == 1);
  CHECK(r.boundary_edges == 2);
  CHECK_FALSE(r.closed());
}

TEST_CASE("Overlapping shells self-intersect, separate shells do not", "[mesh]") {
  TriangleMesh two = box_mesh({0, 0, 0}, {1, 1, 1});
  const double shift = GENERATE(0.5, 2.0);
  append(two, box_mesh({shift, 0.25, 0.25}, {shift + 1, 0.75, 0.75}));
  const MeshReport r = check_mesh(two);
  CHECK(r.encloses_volume());
  if (shift < 1) {
    CHECK(r.self_intersecting_pairs > 0);
    CHECK_FALSE(r.is_valid_solid());
  } else {
    CHECK(r.self_intersecting_pairs == 0);
    CHECK(r.is_valid_solid());
    CHECK(r.volume == Approx(1.0 + 0.25));
  }
  CHECK_FALSE(check_mesh(two, false).self_intersections_searched);
}
