// The stall rules (NewtonOptions::stall_window): a Newton solve whose projected steps converge
// linearly, too slowly to reach the tolerance within its budget, stops at once, and so does
// one whose residual sets no new best for 2 x stall_window steps; solves whose rate fits their
// budget, or whose residual rises and falls between true-tangent and projected steps, are
// left alone.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "point_blocks.hpp"
#include "statics/projected_newton.hpp"

using namespace latmpm;
using namespace latmpm::statics;

namespace {
// A platen step (not at rest) from 1, then `steps` projected steps at rest from r0, each × rate.
struct History {
  std::vector<Real> residual{1};
  std::vector<char> projected_at_rest{0};
  History(Real r0, Real rate, int steps) {
    residual.push_back(r0);
    for (int i = 0; i < steps; ++i) {
      residual.push_back(residual.back() * rate);
      projected_at_rest.push_back(1);
    }
  }
};

// The 4 mm neo-Hookean cube (1 mm cells) between clamped platens, the top moved down 40 %
// in one solve from rest: its report, and u the result.
NewtonReport solve_compressed_cube(const NewtonOptions& options, Vector& u) {
  const Real h = 1e-3;
  StaticProblem problem = test::neo_hookean_cube(h);
  Dirichlet dirichlet(problem.dof_count());
  for (size_t n = 0; n < problem.band().node_count(); ++n) {
    const int k = problem.band().node[n][2];
    if (k <= 0) dirichlet.prescribe(n, Vec3::Zero());
    if (k >= 4) dirichlet.prescribe(n, Vec3(0, 0, -0.4 * 4 * h));
  }
  u = Vector::Zero(Eigen::Index(problem.dof_count()));
  SparseSolver solver(LinearSolverKind::cholmod);
  return solve_equilibrium(problem, dirichlet, u, solver, options);
}

NewtonOptions budget(int max_iterations) {
  NewtonOptions options;
  options.tolerance = 1e-8;
  options.max_iterations = max_iterations;
  options.stall_window = 4;  // the static run's default (the library's is 0)
  return options;
}
}  // namespace

TEST_CASE("Steady linear convergence that cannot reach the tolerance in the budget stops the solve",
          "[statics]") {
  // 1e-2 × 0.8 a step: after the platen step and 4 projected ones (5 steps taken), the
  // tolerance 1e-8 is ceil(ln(1e-8 / (1e-2 · 0.8⁴)) / ln 0.8) = 58 steps away.
  const History h(1e-2, 0.8, 4);
  const Real now = 1e-2 * std::pow(0.8, 4);
  const int needed = int(std::ceil(std::log(1e-8 / now) / std::log(0.8)));
  REQUIRE(needed == 58);
  const std::string stop = linear_convergence_stall(h.residual, h.projected_at_rest, budget(20));
  CHECK_THAT(stop, Catch::Contains("converging linearly") && Catch::Contains("x0.8 a step") &&
                       Catch::Contains("58 more steps") && Catch::Contains("15 left"));
  // The same history with a budget that holds those steps goes on; one step short stops.
  CHECK(linear_convergence_stall(h.residual, h.projected_at_rest, budget(5 + needed)).empty());
  CHECK_FALSE(linear_convergence_stall(h.residual, h.projected_at_rest, budget(5 + needed - 1)).empty());
  // Too few steps at rest to judge, or the rule off.
  const History short_history(1e-2, 0.8, 3);
  CHECK(linear_convergence_stall(short_history.residual, short_history.projected_at_rest, budget(20)).empty());
  NewtonOptions off = budget(20);
  off.stall_window = 0;
  CHECK(linear_convergence_stall(h.residual, h.projected_at_rest, off).empty());
}

TEST_CASE("Fast, rising or true-tangent steps are not a stall", "[statics]") {
  // Faster than stall_ratio (0.6) a step: superlinear or near it, not the stall.
  const History fast(1e-2, 0.5, 6);
  CHECK(linear_convergence_stall(fast.residual, fast.projected_at_rest, budget(8)).empty());
  // A rise inside the window (the alternation of true-tangent and projected steps of a
  // converging increment, docs/statics.md): not steady.
  History rising(1e-2, 0.8, 4);
  rising.residual[3] *= 2;
  CHECK(linear_convergence_stall(rising.residual, rising.projected_at_rest, budget(20)).empty());
  // A true-tangent step inside the window.
  History true_step(1e-2, 0.8, 4);
  true_step.projected_at_rest[2] = 0;
  CHECK(linear_convergence_stall(true_step.residual, true_step.projected_at_rest, budget(20)).empty());
}

TEST_CASE("A converging solve takes the same steps with the stall rules as without them", "[statics]") {
  // The neo-Hookean cube compressed 40 % by projected steps only (the true tangent never
  // tried): linear convergence at ~x0.45 a step, which the linear rule examines at every
  // step once stall_ratio is lowered to 0.3; with a budget that holds the solve it must
  // never act. Then the default solve (true tangent from the second step).
  for (const bool projected_only : {true, false}) {
    std::vector<Vector> results;
    std::vector<int> iterations;
    for (const int window : {4, 0}) {
      NewtonOptions options = budget(40);
      options.stall_window = window;
      if (projected_only) options.true_tangent_below = 0, options.stall_ratio = 0.3;
      int projected_at_rest = 0;
      options.on_step = [&](const NewtonStep& s) { projected_at_rest += s.iteration > 1 && !s.true_tangent; };
      Vector u;
      const NewtonReport report = solve_compressed_cube(options, u);
      REQUIRE(report.converged);
      if (projected_only) CHECK(projected_at_rest >= 10);  // the window was filled, many times
      results.push_back(u);
      iterations.push_back(report.iterations);
    }
    CHECK(iterations[0] == iterations[1]);
    CHECK((results[0] - results[1]).norm() == 0);
  }
}

TEST_CASE("Inside a solve, the rules stop linear creep and round-off, counted from the platen step",
          "[statics]") {
  // Linear creep: the projected-only solve above with a budget of 15 steps, which it cannot
  // meet at x0.45 a step from 0.128 to 1e-8 (23 steps). It stops early, by the linear rule,
  // on the same residuals as the solve with a budget that holds it.
  NewtonOptions creep = budget(15);
  creep.tolerance = 1e-8;
  creep.true_tangent_below = 0;
  creep.stall_ratio = 0.3;
  Vector u;
  const NewtonReport stopped = solve_compressed_cube(creep, u);
  CHECK_FALSE(stopped.converged);
  CHECK_THAT(stopped.failure, Catch::Contains("converging linearly"));
  CHECK(stopped.iterations < 15);
  creep.max_iterations = 40;
  const NewtonReport finished = solve_compressed_cube(creep, u);
  REQUIRE(finished.converged);
  CHECK(finished.iterations > 15);
  for (size_t i = 0; i < stopped.residual.size(); ++i) CHECK(stopped.residual[i] == finished.residual[i]);

  // Round-off: a tolerance no solve reaches. The residual falls to ~1e-15 and then wanders;
  // the solve stops 2 x 4 steps after its best, counted from the first residual with the
  // platen in place (index 1: the start's residual, 0, comes before the platen moves and
  // would stop the solve at step 8).
  NewtonOptions unreachable = budget(50);
  unreachable.tolerance = 1e-30;
  const NewtonReport wander = solve_compressed_cube(unreachable, u);
  CHECK_FALSE(wander.converged);
  CHECK_THAT(wander.failure, Catch::Contains("no progress"));
  const auto best = std::min_element(wander.residual.begin() + 1, wander.residual.end());
  CHECK(*best < 1e-13);
  CHECK(wander.iterations == int(best - wander.residual.begin()) + 8);
  CHECK(wander.iterations < 50);
}

TEST_CASE("A solve that fails tells why once; a converged one never", "[statics]") {
  for (const int max_iterations : {1, 50}) {
    NewtonOptions options;
    options.max_iterations = max_iterations;
    std::vector<std::string> told;
    options.on_failure = [&](const std::string& why) { told.push_back(why); };
    Vector u;
    const NewtonReport report = solve_compressed_cube(options, u);
    if (report.converged) {
      CHECK(told.empty());
    } else {
      REQUIRE(told.size() == 1);
      CHECK(told[0] == report.failure);
      CHECK_THAT(told[0], Catch::Contains("no convergence in 1 Newton steps"));
    }
    CHECK(report.converged == (max_iterations == 50));
  }
}

TEST_CASE("A residual that sets no new best for twice the window stops the solve", "[statics]") {
  // Before the platen step the last equilibrium's 1e-10 does not count (first_at_rest = 1);
  // the best, 1e-4, is reached at index 2, then the residual bounces above it.
  std::vector<Real> residual{1e-10, 1e-2, 1e-4};
  for (int i = 0; i < 7; ++i) residual.push_back(i % 2 ? 3e-4 : 2e-3);
  const NewtonOptions options = budget(20);
  CHECK(no_progress_stall(residual, 1, options).empty());  // 7 steps since the best
  residual.push_back(5e-4);
  CHECK_THAT(no_progress_stall(residual, 1, options),
             Catch::Contains("no progress") && Catch::Contains("0.0001") && Catch::Contains("for 8 steps"));
  // A new best restarts the count; counted from index 0 the platen step's 1e-10 would be
  // the best and stop every solve.
  residual.push_back(9e-5);
  CHECK(no_progress_stall(residual, 1, options).empty());
  CHECK_FALSE(no_progress_stall(residual, 0, options).empty());
  NewtonOptions off = options;
  off.stall_window = 0;
  CHECK(no_progress_stall(std::vector<Real>(30, 1.0), 0, off).empty());
}

