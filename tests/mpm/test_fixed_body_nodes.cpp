// A fixed point body's nodes marked from a list made once, its points out of the step
// (fixed_body_nodes.hpp), against the same run with its points scattered every step: the two
// must be the same run, bit for bit, for every shape function and scheme that marks nodes
// (its only contribution: the points carry no mass to the grid). The base plate is wider
// than a bucket (8 cells), so some buckets hold its points only; a second fixed body touches
// it, so nodes both mark take the larger marker in both runs.
#include <catch2/catch.hpp>

#include <cstring>

#include "mpm/simulation.hpp"
#include "point_builders.hpp"

using namespace latmpm;
using namespace latmpm::mpm;
using namespace latmpm::mpm::test;

namespace {
struct Outcome {
  Particles particles;
  StepDiagnostics diagnostics;
};

Outcome run_column_on_plate(ShapeFunctionKind shape, UpdateScheme scheme, bool marked_once, int steps) {
  const Real h = 0.4e-3, w = 1.6e-3, L = 4.8e-3, rho = 1050, speed = 0.5;
  PointSet points = empty_point_set(h, 2);
  // The column leans over a bucket border (x = 8 h) and stands off-centre on the base.
  add_points(points, Eigen::Vector3d(7 * h, 3 * h, 0), Eigen::Vector3d(7 * h + w, 3 * h + w, L), "column");
  add_points(points, Eigen::Vector3d(-6 * h, -6 * h, -2 * h), Eigen::Vector3d(18 * h, 18 * h, 0), "base");
  add_points(points, Eigen::Vector3d(18 * h, -6 * h, -2 * h), Eigen::Vector3d(20 * h, 18 * h, h), "kerb");
  add_points(points, Eigen::Vector3d(7 * h, 3 * h, L), Eigen::Vector3d(7 * h + w, 3 * h + w, L + 2 * h), "plate");
  Settings s;
  s.cell_size = h;
  s.shape_function = shape;
  s.scheme = scheme;
  s.threads = 2;
  s.cfl = 0.3;
  s.gravity = Vec3(0.3, 0, -9.81) * 1000;  // a sideways pull, so the column bends onto its base's nodes
  s.mark_fixed_bodies_once = marked_once;
  Simulation sim(points,
                 {deformable("column", elastic(10e6, 0.3, rho)), rigid("base", BodyRole::fixed, Vec3::Zero(), rho),
                  rigid("kerb", BodyRole::fixed, Vec3::Zero(), rho),
                  rigid("plate", BodyRole::driven, Vec3(0, 0, -speed), rho)},
                 s);
  for (int i = 0; i < steps; ++i) sim.step();
  return {sim.particles(), sim.last_diagnostics()};
}

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}
}  // namespace

TEST_CASE("Fixed bodies marked once give the run their points give when scattered every step",
          "[mpm][fixed-bodies]") {
  const auto [shape, scheme] = GENERATE(table<ShapeFunctionKind, UpdateScheme>({
      {ShapeFunctionKind::ugimp, UpdateScheme::usl},
      {ShapeFunctionKind::cpgimp, UpdateScheme::usl},
      {ShapeFunctionKind::bspline2, UpdateScheme::usl},
      {ShapeFunctionKind::bspline3, UpdateScheme::usf},
      {ShapeFunctionKind::linear, UpdateScheme::musl},
      {ShapeFunctionKind::ddmp, UpdateScheme::usl},
      {ShapeFunctionKind::ddmp, UpdateScheme::musl},
  }));
  INFO("shape " << int(shape) << ", scheme " << int(scheme));
  const int steps = 120;
  const Outcome once = run_column_on_plate(shape, scheme, true, steps);
  const Outcome every = run_column_on_plate(shape, scheme, false, steps);
  // The run did something: the column was pressed and the base carried load.
  REQUIRE(once.diagnostics.step == steps);
  REQUIRE(std::abs(once.diagnostics.reaction[1][2]) > 0);
  REQUIRE(std::abs(once.diagnostics.reaction[2][0]) + std::abs(every.diagnostics.reaction[1][0]) > 0);
  CHECK(same_bits(once.particles.position, every.particles.position));
  CHECK(same_bits(once.particles.velocity, every.particles.velocity));
  CHECK(same_bits(once.particles.deformation, every.particles.deformation));
  CHECK(same_bits(once.particles.stress, every.particles.stress));
  CHECK(same_bits(once.particles.id, every.particles.id));
  for (size_t b = 0; b < 4; ++b) {
    INFO("body " << b);
    CHECK(once.diagnostics.reaction[b] == every.diagnostics.reaction[b]);
  }
  CHECK(once.diagnostics.kinetic_energy == every.diagnostics.kinetic_energy);
  CHECK(once.diagnostics.strain_energy == every.diagnostics.strain_energy);
  CHECK(once.diagnostics.time == every.diagnostics.time);
}
