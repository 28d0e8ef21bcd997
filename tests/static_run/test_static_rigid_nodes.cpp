// A scene's rigid half-spaces hold, in the static solve, the band nodes the explicit solver
// couples to them (libs/mpm/rigid_body.hpp): those whose support, the open cube of half-width
// h around the node, overlaps the half-space. Expected sets written out from that geometry.
#include <catch2/catch.hpp>

#include <cmath>
#include <set>

#include "static_run/static_scene_problem.hpp"

using namespace latmpm;

namespace {
constexpr double h = 1e-3;

// A 4 mm cube of linear elastic points (1 mm cells, 2 points per cell and direction), a
// fixed half-space below at z = base_z (normal +z) and a driven one above at z = platen_z
// (normal −z).
void specimen(Scene& scene, PointSet& points, double base_z, double platen_z) {
  scene.settings.cell_size = points.cell_size = h;
  scene.settings.shape_function = mpm::ShapeFunctionKind::ugimp;
  scene.solver.kind = SolverSpec::static_equilibrium;
  scene.end.kind = EndCondition::plate_displacement;
  scene.end.value = 1e-4;
  points.ppc = 2;
  points.body_names = {"part"};
  scene.bodies.resize(1);
  scene.bodies[0].name = "part";
  scene.bodies[0].role = BodyRole::deformable;
  scene.bodies[0].material.kind = mpm::MaterialKind::linear_elastic;
  scene.bodies[0].material.young_modulus = 1e7;
  scene.bodies[0].material.poisson_ratio = 0.3;
  scene.bodies[0].material.density = 1000;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j)
      for (int k = 0; k < 8; ++k) points.position.emplace_back((i + 0.5) * h / 2, (j + 0.5) * h / 2, (k + 0.5) * h / 2);
  points.body.assign(points.position.size(), 0);
  points.half_size.assign(points.position.size(), Eigen::Vector3d::Constant(h / 4));
  points.volume.assign(points.position.size(), h * h * h / 8);
  RigidBodySpec base, platen;
  base.name = "base", platen.name = "platen";
  base.shape = platen.shape = mpm::RigidShape::half_space;
  base.motion = mpm::RigidMotion::fixed;
  base.plane_point = {0, 0, base_z};
  base.plane_normal = {0, 0, 1};
  platen.motion = mpm::RigidMotion::driven;
  platen.plane_point = {0, 0, platen_z};
  platen.plane_normal = {0, 0, -1};
  platen.velocity = {0, 0, -0.1};
  scene.rigid_bodies = {base, platen};
}

// The node layers (z / h) of a node set.
std::set<long> layers(const StaticSceneProblem& sp, const std::vector<size_t>& nodes) {
  std::set<long> out;
  for (size_t n : nodes) out.insert(std::lround(sp.problem->band().node_position(n).z() / h));
  return out;
}
}  // namespace

TEST_CASE("Static rigid half-spaces hold the nodes the explicit solver couples", "[static_run]") {
  // Planes between node planes: the base at z = 0.5 mm couples the nodes with z < 1.5 mm,
  // the platen at 3.5 mm those with z > 2.5 mm (the nodes inside the half-spaces alone would
  // miss the layers z = 1 mm and z = 3 mm).
  Scene scene;
  PointSet points;
  specimen(scene, points, 0.5e-3, 3.5e-3);
  const StaticSceneProblem sp = make_static_problem(scene, points);
  const std::set<long> all = layers(sp, [&] {
    std::vector<size_t> every(sp.problem->band().node_count());
    for (size_t n = 0; n < every.size(); ++n) every[n] = n;
    return every;
  }());
  // uGIMP with 2 points per cell: the stencils end on the node planes z = -1 and 5 mm, where
  // the weights are zero, so the band is the nodes 0 … 4 mm.
  REQUIRE(all == std::set<long>{0, 1, 2, 3, 4});
  CHECK(layers(sp, sp.loading.support_nodes) == std::set<long>{0, 1});
  CHECK(layers(sp, sp.loading.platen_nodes) == std::set<long>{3, 4});
  CHECK(sp.contact_gap == 0);
}

TEST_CASE("A static rigid half-space short of the material first closes the gap", "[static_run]") {
  // The platen at 7 mm: the highest band nodes (4 mm) are coupled once the plane is within a
  // cell of them, after 2 mm of travel; that layer alone is held.
  Scene scene;
  PointSet points;
  specimen(scene, points, 0.5e-3, 7e-3);
  const StaticSceneProblem sp = make_static_problem(scene, points);
  CHECK(sp.contact_gap == Approx(2e-3).epsilon(1e-9));
  CHECK(layers(sp, sp.loading.platen_nodes) == std::set<long>{4});
}
