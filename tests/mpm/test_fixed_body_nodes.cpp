// A fixed point body's nodes marked from a list made once, its points out of the step
// (fixed_body_nodes.hpp), against the same run with its points scattered every step: the two
// must be the same run, bit for bit, for every shape function and scheme that marks nodes
// (its only contribution: the points carry no mass to the grid). The base plate is wider
// than a bucket (8 cells), so some buckets hold its points only; a second fixed body, a collar
// around the column's foot, marks nodes the base marks too and the column gives mass, so the
// larger marker must win there as in the scatter (each body's reaction tells). The driven
// plate crosses cells, so the particles are re-sorted during the run; half-way, every fixed
// point is given a velocity through mutable_particles(), which the step must set back to zero.
#include <catch2/catch.hpp>

#include <cstring>

#include "mpm/simulation.hpp"
#include "mpm/simulation_test_access.hpp"
#include "point_builders.hpp"

using namespace latmpm;
using namespace latmpm::mpm;
using namespace latmpm::mpm::test;

namespace {
struct Outcome {
  Particles particles;
  StepDiagnostics diagnostics;
};

Outcome run_column_on_plate(ShapeFunctionKind shape, UpdateScheme scheme, bool marked_once, int steps,
                            size_t* grid_nodes) {
  const Real h = 0.4e-3, w = 1.6e-3, L = 4.8e-3, rho = 1050, speed = 4;
  PointSet points = empty_point_set(h, 2);
  // The column stands over a bucket border (x = 8 h), off-centre on the base.
  const Eigen::Vector3d lo(7 * h, 3 * h, 0), hi(7 * h + w, 3 * h + w, L);
  add_points(points, lo, hi, "column");
  add_points(points, Eigen::Vector3d(-6 * h, -6 * h, -2 * h), Eigen::Vector3d(18 * h, 18 * h, 0), "base");
  // The collar: one cell high around the foot, against the column's sides.
  add_points(points, Eigen::Vector3d(lo[0] - 2 * h, lo[1] - 2 * h, 0), Eigen::Vector3d(lo[0], hi[1] + 2 * h, h), "collar");
  add_points(points, Eigen::Vector3d(hi[0], lo[1] - 2 * h, 0), Eigen::Vector3d(hi[0] + 2 * h, hi[1] + 2 * h, h), "collar");
  add_points(points, Eigen::Vector3d(lo[0], lo[1] - 2 * h, 0), Eigen::Vector3d(hi[0], lo[1], h), "collar");
  add_points(points, Eigen::Vector3d(lo[0], hi[1], 0), Eigen::Vector3d(hi[0], hi[1] + 2 * h, h), "collar");
  add_points(points, Eigen::Vector3d(lo[0], lo[1], L), Eigen::Vector3d(hi[0], hi[1], L + 2 * h), "plate");
  Settings s;
  s.cell_size = h;
  s.shape_function = shape;
  s.scheme = scheme;
  s.threads = 2;
  s.cfl = 0.3;
  s.gravity = Vec3(3000, 0, -9810);  // a sideways pull: the column bends against the collar
  s.mark_fixed_bodies_once = marked_once;
  Simulation sim(points,
                 {deformable("column", elastic(10e6, 0.3, rho)), rigid("base", BodyRole::fixed, Vec3::Zero(), rho),
                  rigid("collar", BodyRole::fixed, Vec3::Zero(), rho),
                  rigid("plate", BodyRole::driven, Vec3(0, 0, -speed), rho)},
                 s);
  for (int i = 0; i < steps; ++i) {
    if (i == steps / 2) {
      Particles& ps = sim.mutable_particles();
      for (size_t p = 0; p < ps.size(); ++p)
        if (ps.body[p] == 1 || ps.body[p] == 2) ps.velocity[p] = Vec3(1, 2, 3).cast<ParticleReal>();
    }
    sim.step();
  }
  *grid_nodes = SimulationTestAccess::grid_nodes(sim).size();
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
      {ShapeFunctionKind::ddmp, UpdateScheme::usf},
  }));
  INFO("shape " << int(shape) << ", scheme " << int(scheme));
  const int steps = 300;
  size_t nodes_once = 0, nodes_every = 0;
  const Outcome once = run_column_on_plate(shape, scheme, true, steps, &nodes_once);
  const Outcome every = run_column_on_plate(shape, scheme, false, steps, &nodes_every);
  // The run did something: the plate moved past a cell (re-sorts), and the base and the
  // collar both carried load; and the new path ran: the base's points no longer hold blocks.
  REQUIRE(once.diagnostics.step == steps);
  REQUIRE(once.diagnostics.body_displacement[3].norm() > 0.4e-3);
  REQUIRE(once.diagnostics.reaction[1].norm() > 0);
  REQUIRE(once.diagnostics.reaction[2].norm() > 0);
  INFO("grid nodes: marked once " << nodes_once << ", scattered " << nodes_every);
  CHECK(nodes_once < nodes_every);
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
