// Adaptive load continuation (statics/load_continuation.hpp) on a slender neo-Hookean
// cantilever whose tip load bends it through a large rotation: where one bounded projected
// Newton solve from rest fails, load steps from rest reach the equilibrium that an unbounded
// solve finds (a stable minimum: the same one); from that equilibrium a slightly different
// load converges at once under the whole load, in fewer Newton steps than from rest.
#include <catch2/catch.hpp>

#include "point_blocks.hpp"
#include "statics/load_continuation.hpp"

using namespace latmpm;
using namespace latmpm::statics;

namespace {

struct Cantilever {
  StaticProblem problem;
  Dirichlet dirichlet;
  std::vector<Vec3> force;
};

// 20 × 2 × 2 mm, clamped at x = 0; tip load F along −y on the points of the last cell.
// Linear bending would give δ = F L³ / (3 E I) = 0.2 m/N × F (F = 0.05 N: half the span).
void build(Cantilever& c, Real load) {
  const Real h = 1e-3;
  c.dirichlet = Dirichlet(c.problem.dof_count());
  for (size_t n = 0; n < c.problem.band().node_count(); ++n)
    if (c.problem.band().node[n][0] <= 0) c.dirichlet.prescribe(n, Vec3::Zero());
  const auto& band = c.problem.band();
  c.force.assign(c.problem.point_count(), Vec3::Zero());
  std::vector<size_t> tip;
  for (size_t p = 0; p < c.problem.point_count(); ++p) {
    Vec3 X = Vec3::Zero();
    for (uint32_t e = band.point_offset[p]; e < band.point_offset[p + 1]; ++e)
      X += band.entry_weight[e] * band.node_position(band.entry_node[e]);
    if (X[0] > 19 * h) tip.push_back(p);
  }
  for (size_t p : tip) c.force[p] = Vec3(0, -load / Real(tip.size()), 0);
}

}  // namespace

TEST_CASE("Load continuation reaches the large-rotation equilibrium a bounded Newton solve misses", "[statics]") {
  const Real h = 1e-3;
  const test::PointBlock block = test::point_block(Vec3::Zero(), Vec3(20 * h, 2 * h, 2 * h), h, 2);
  Cantilever c{test::make_problem(block, h, mpm::ShapeFunctionKind::linear,
                                  test::material(mpm::MaterialKind::neo_hookean, 1e7, 0.3)),
               Dirichlet(), {}};
  c.problem.set_stabilisation(0.1);
  build(c, 0.05);
  SparseSolver solver(LinearSolverKind::cholmod);

  LoadContinuation bounded;
  bounded.newton.tolerance = 1e-10;
  bounded.newton.max_iterations = 8;
  LoadContinuation whole = bounded;
  whole.first_step = 1;
  whole.max_increments = 1;  // the whole load from rest, nothing else
  Vector u_once = Vector::Zero(Eigen::Index(c.problem.dof_count()));
  const ContinuationReport once = solve_by_load_continuation(c.problem, c.dirichlet, c.force, u_once, solver, whole);
  CHECK_FALSE(once.converged);
  CHECK(once.failure.find("load step 1") != std::string::npos);

  Vector u = Vector::Zero(Eigen::Index(c.problem.dof_count()));
  const ContinuationReport stepped = solve_by_load_continuation(c.problem, c.dirichlet, c.force, u, solver, bounded);
  CAPTURE(stepped.failure, stepped.steps, stepped.failed_steps);
  REQUIRE(stepped.converged);
  CHECK(stepped.steps >= 2);
  CHECK(stepped.load_factor == 1);
  CHECK(c.problem.min_jacobian(u) > 0);

  // The unbounded solve from rest under the whole load: the same equilibrium.
  NewtonOptions patient = bounded.newton;
  patient.max_iterations = 500;
  c.problem.set_point_forces(c.force);
  Vector u_long = Vector::Zero(Eigen::Index(c.problem.dof_count()));
  const NewtonReport long_solve = solve_equilibrium(c.problem, c.dirichlet, u_long, solver, patient);
  REQUIRE(long_solve.converged);
  CHECK(long_solve.iterations > bounded.newton.max_iterations);
  CHECK((u - u_long).norm() <= 1e-6 * u_long.norm());
  // A large rotation: the tip moves down by a good part of the span.
  Real tip = 0;
  for (Eigen::Index i = 1; i < u.size(); i += 3) tip = std::min(tip, u[i]);
  CHECK(tip < -5 * h);

  // A 5 % larger load from this equilibrium: the whole load at once, fewer steps than from rest.
  build(c, 0.0525);
  Vector u_next = u;
  const ContinuationReport warm = solve_by_load_continuation(c.problem, c.dirichlet, c.force, u_next, solver, bounded);
  REQUIRE(warm.converged);
  CHECK(warm.from_start);
  Vector u_cold = Vector::Zero(Eigen::Index(c.problem.dof_count()));
  const ContinuationReport cold = solve_by_load_continuation(c.problem, c.dirichlet, c.force, u_cold, solver, bounded);
  REQUIRE(cold.converged);
  CHECK(warm.newton_iterations < cold.newton_iterations);
  CHECK((u_next - u_cold).norm() <= 1e-6 * u_cold.norm());
}
