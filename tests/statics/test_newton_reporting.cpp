// What projected Newton tells its caller while it runs: each step as it is taken
// (NewtonOptions::on_step, the run log's Newton lines), and a stop asked between steps
// (NewtonOptions::stop_requested, a signal) that ends the solve, or the whole path, where it
// stands without retries or bisection.
#include <catch2/catch.hpp>

#include <vector>

#include "point_blocks.hpp"
#include "statics/displacement_control.hpp"
#include "statics/projected_newton.hpp"

using namespace latmpm;
using namespace latmpm::statics;

namespace {
// The 4 mm neo-Hookean cube between clamped platens, the top moved down by `travel`.
Dirichlet compressed(const StaticProblem& problem, Real travel) {
  Dirichlet dirichlet(problem.dof_count());
  for (size_t n = 0; n < problem.band().node_count(); ++n) {
    const int k = problem.band().node[n][2];
    if (k <= 0) dirichlet.prescribe(n, Vec3::Zero());
    if (k >= 4) dirichlet.prescribe(n, Vec3(0, 0, -travel));
  }
  return dirichlet;
}
}  // namespace

TEST_CASE("Newton tells every step it takes, as its report records them", "[statics]") {
  const Real h = 1e-3;
  StaticProblem problem = test::neo_hookean_cube(h);
  Vector u = Vector::Zero(Eigen::Index(problem.dof_count()));
  SparseSolver solver(LinearSolverKind::cholmod);
  std::vector<NewtonStep> steps;
  NewtonOptions options;
  options.on_step = [&](const NewtonStep& s) { steps.push_back(s); };
  const NewtonReport report = solve_equilibrium(problem, compressed(problem, 0.4 * h), u, solver, options);
  REQUIRE(report.converged);
  REQUIRE(int(steps.size()) == report.iterations);
  REQUIRE(report.iterations >= 2);
  for (size_t k = 0; k < steps.size(); ++k) {
    CHECK(steps[k].iteration == int(k) + 1);
    CHECK(steps[k].residual_before == report.residual[k]);
    CHECK(steps[k].alpha == report.step[k]);
  }
  int true_tangent = 0;
  for (const NewtonStep& s : steps) true_tangent += s.true_tangent;
  CHECK(true_tangent == report.true_tangent_steps);
}

TEST_CASE("A stop asked between Newton steps ends the solve unconverged, not failed", "[statics]") {
  const Real h = 1e-3;
  StaticProblem problem = test::neo_hookean_cube(h);
  Vector u = Vector::Zero(Eigen::Index(problem.dof_count()));
  SparseSolver solver(LinearSolverKind::cholmod);
  int taken = 0;
  NewtonOptions options;
  options.on_step = [&](const NewtonStep&) { ++taken; };
  options.stop_requested = [&] { return taken == 2; };
  const NewtonReport report = solve_equilibrium(problem, compressed(problem, 0.4 * h), u, solver, options);
  CHECK_FALSE(report.converged);
  CHECK(report.stopped);
  CHECK(report.iterations == 2);
  CHECK(problem.min_jacobian(u) > 0);
}

TEST_CASE("A stop asked during a path ends it at the last converged increment", "[statics]") {
  StaticProblem problem = test::neo_hookean_cube(1e-3);
  const PlatenLoading loading = test::clamped_platens(problem, 4, 0.3 * 4e-3, 10);
  SparseSolver solver(LinearSolverKind::cholmod);
  int increments_seen = 0;
  NewtonOptions options;
  // Asked before every Newton step and every increment: true once three increments converged.
  options.stop_requested = [&] { return increments_seen == 3; };
  const PathReport path =
      load_by_platen(problem, loading, solver, options, [&](const PathPoint&, const Vector&) { ++increments_seen; });
  REQUIRE(path.ended);
  CHECK(path.stopped);
  CHECK(path.end_reason == "stopped");
  REQUIRE(path.points.size() == 3);
  CHECK(path.last_stable_travel == Approx(3 * loading.travel / loading.increments));
  CHECK(path.end_travel == path.last_stable_travel);
  CHECK(path.last_stable_load == path.points.back().load);
  CHECK(path.last_stable_load > 0);
}

TEST_CASE("A stop asked inside an increment's Newton solve ends the path at the increment before", "[statics]") {
  StaticProblem problem = test::neo_hookean_cube(1e-3);
  const PlatenLoading loading = test::clamped_platens(problem, 4, 0.3 * 4e-3, 4);
  // First the whole path, for the number of Newton steps of the first increment.
  SparseSolver whole_solver(LinearSolverKind::cholmod);
  const PathReport whole = load_by_platen(problem, loading, whole_solver);
  REQUIRE_FALSE(whole.ended);
  REQUIRE(whole.points.size() == 4);
  const int first = whole.points[0].newton_iterations;
  REQUIRE(whole.points[1].newton_iterations >= 2);
  // Then stopped after the first step of the second increment's solve.
  SparseSolver solver(LinearSolverKind::cholmod);
  int steps = 0;
  NewtonOptions options;
  options.on_step = [&](const NewtonStep&) { ++steps; };
  options.stop_requested = [&] { return steps == first + 1; };
  const PathReport path = load_by_platen(problem, loading, solver, options);
  REQUIRE(path.stopped);
  CHECK(steps == first + 1);  // no retry, no bisection after the stop
  REQUIRE(path.points.size() == 1);
  CHECK(path.points[0].load == Approx(whole.points[0].load).epsilon(1e-9));
  CHECK(path.last_stable_travel == Approx(loading.travel / 4));
}
