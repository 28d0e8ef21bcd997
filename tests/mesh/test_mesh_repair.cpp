// Repair: each defect is introduced into a mesh of known volume, repaired, and the result
// must be a valid solid with the original volume.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "mesh/mesh_checks.hpp"
#include "mesh/mesh_repair.hpp"
#include "mesh/primitive_meshes.hpp"

using namespace latmpm;

namespace {
void flip(std::array<int32_t, 3>& t) { std::swap(t[1], t[2]); }
}  // namespace

TEST_CASE("Repair closes a hole in a box and restores its volume", "[mesh]") {
  TriangleMesh box = box_mesh({0, 0, 0}, {0.01, 0.02, 0.03});
  box.triangles.erase(box.triangles.begin() + 5);
  REQUIRE_FALSE(check_mesh(box).closed());
  const RepairReport rep = repair_mesh(box);
  // The hole lies in a face of the bounding box: a planar cap (test_box_face_caps.cpp).
  CHECK(rep.loops_capped == 1);
  CHECK(rep.cap_faces_added == 1);
  CHECK(rep.holes_filled == 0);
  const MeshReport r = check_mesh(box);
  CHECK(r.is_valid_solid());
  CHECK(r.volume == Approx(0.01 * 0.02 * 0.03).epsilon(1e-12));
}

TEST_CASE("Repair refills the fan of faces removed around a sphere vertex", "[mesh]") {
  TriangleMesh sphere = sphere_mesh({0, 0, 0}, 1.0, 2);
  const double exact = check_mesh(sphere).volume;
  const size_t faces = sphere.triangles.size();
  sphere.triangles.erase(std::remove_if(sphere.triangles.begin(), sphere.triangles.end(),
                                        [](const auto& t) { return t[0] == 0 || t[1] == 0 || t[2] == 0; }),
                         sphere.triangles.end());
  const size_t removed = faces - sphere.triangles.size();
  REQUIRE(removed == 5);  // an icosahedron vertex has five neighbours
  CHECK(check_mesh(sphere).boundary_edges == 5);
  const RepairReport rep = repair_mesh(sphere);
  CHECK(rep.holes_filled == 1);
  CHECK(rep.hole_faces_added == 3);  // a pentagon needs three triangles
  const MeshReport r = check_mesh(sphere);
  CHECK(r.is_valid_solid());
  // The flat pentagon cuts off a cap: the volume drops, but by less than the cap's 1 %.
  CHECK(r.volume < exact);
  CHECK(r.volume > 0.99 * exact);
}

TEST_CASE("Repair orients inside-out and partly flipped meshes outward", "[mesh]") {
  TriangleMesh sphere = sphere_mesh({1, 2, 3}, 0.5, 2);
  const double exact = check_mesh(sphere).volume;
  for (auto& t : sphere.triangles) flip(t);
  const size_t flipped = GENERATE(0, 1, 7);  // additionally flip some back
  for (size_t i = 0; i < flipped; ++i) flip(sphere.triangles[i * 11]);
  const RepairReport rep = repair_mesh(sphere);
  const MeshReport r = check_mesh(sphere);
  CHECK(r.is_valid_solid());
  CHECK(r.volume == Approx(exact).epsilon(1e-12));
  CHECK_FALSE(rep.actions.empty());
}

TEST_CASE("Repair removes degenerate and duplicate faces", "[mesh]") {
  TriangleMesh box = box_mesh({0, 0, 0}, {1, 1, 1});
  box.triangles.push_back(box.triangles[0]);
  box.triangles.push_back({box.triangles[3][2], box.triangles[3][1], box.triangles[3][0]});
  box.triangles.push_back({2, 2, 3});
  const RepairReport rep = repair_mesh(box);
  CHECK(rep.degenerate_faces_removed == 1);
  CHECK(rep.duplicate_faces_removed == 2);
  const MeshReport r = check_mesh(box);
  CHECK(r.is_valid_solid());
  CHECK(r.volume == Approx(1.0));
}

TEST_CASE("Repair stitches a seam of coincident but unshared vertices", "[mesh]") {
  TriangleMesh box = box_mesh({0, 0, 0}, {1, 1, 1});
  // Give the two top triangles their own copies of the four top vertices.
  for (int face = 2; face <= 3; ++face)
    for (auto& v : box.triangles[face]) {
      box.vertices.push_back(box.vertices[v]);
      v = static_cast<int32_t>(box.vertices.size() - 1);
    }
  REQUIRE_FALSE(check_mesh(box).closed());
  repair_mesh(box);
  const MeshReport r = check_mesh(box);
  CHECK(r.is_valid_solid());
  CHECK(r.volume == Approx(1.0));
}

TEST_CASE("Repair leaves holes larger than the limit open", "[mesh]") {
  TriangleMesh can = cylinder_mesh({0, 0, 0}, 1.0, 2.0, 64);
  can.triangles.erase(std::remove_if(can.triangles.begin(), can.triangles.end(),
                                     [](const auto& t) { return t[0] == 2 * 64 + 1; }),  // top cap
                      can.triangles.end());
  // A box above the can, so that the opening is not on the bounding box's top face (where
  // it would get a planar cap, test_box_face_caps.cpp).
  append(can, box_mesh({-1, -1, 3}, {1, 1, 4}));
  RepairOptions options;
  options.max_hole_edges = 10;
  const RepairReport rep = repair_mesh(can, options);
  CHECK(rep.holes_left == 1);
  CHECK(rep.holes_filled == 0);
  CHECK_FALSE(check_mesh(can).closed());
}

TEST_CASE("Repair keeps a hollow sphere hollow: the inner shell faces inward", "[mesh]") {
  TriangleMesh shell = sphere_mesh({0, 0, 0}, 2.0, 2);
  TriangleMesh inner = sphere_mesh({0, 0, 0}, 1.0, 2);
  const double outer_v = check_mesh(shell).volume, inner_v = check_mesh(inner).volume;
  append(shell, inner);  // both outward: inconsistent as a solid
  repair_mesh(shell);
  const MeshReport r = check_mesh(shell);
  CHECK(r.is_valid_solid());
  CHECK(r.volume == Approx(outer_v - inner_v).epsilon(1e-12));
}
