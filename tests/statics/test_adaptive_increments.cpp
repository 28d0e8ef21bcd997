// Adaptive increments and the load-maximum vertex of displacement-controlled loading
// (displacement_control.hpp). Each increment is solved to the same tolerance, so on a
// stable path the equilibrium at a travel does not depend on the steps taken to reach it:
// the adaptive path's loads must equal the fixed-increment path's at the travels both visit.
#include <catch2/catch.hpp>

#include <cmath>

#include "point_blocks.hpp"
#include "statics/displacement_control.hpp"

using namespace latmpm;
using namespace latmpm::statics;

TEST_CASE("The load-maximum vertex is the peak of the parabola through three points", "[statics]") {
  auto load = [](Real t) { return 3 - 0.5 * (t - 2.2) * (t - 2.2); };
  const auto [t, f] = parabola_vertex(1, load(1), 2.5, load(2.5), 4, load(4));
  CHECK(t == Approx(2.2).epsilon(1e-12));
  CHECK(f == Approx(3).epsilon(1e-12));
  // Unequal spacing, as adaptive increments give.
  const auto [t2, f2] = parabola_vertex(0.5, load(0.5), 2.0, load(2.0), 2.7, load(2.7));
  CHECK(t2 == Approx(2.2).epsilon(1e-12));
  CHECK(f2 == Approx(3).epsilon(1e-12));
}

TEST_CASE("Adaptive increments follow the fixed-increment path in fewer increments", "[statics]") {
  const Real h = 1e-3, side = 4 * h;
  StaticProblem problem = test::neo_hookean_cube(h);
  PlatenLoading loading = test::clamped_platens(problem, 4, 0.4 * side, 16);
  NewtonOptions newton;
  newton.tolerance = 1e-10;
  auto run = [&](Real growth) {
    loading.max_step_growth = growth;
    SparseSolver solver(LinearSolverKind::cholmod);
    return load_by_platen(problem, loading, solver, newton);
  };
  const PathReport fixed = run(1), adaptive = run(4);
  REQUIRE_FALSE(fixed.ended);
  REQUIRE_FALSE(adaptive.ended);
  REQUIRE(fixed.points.size() == 16);
  CHECK(adaptive.points.size() < fixed.points.size());
  CHECK(adaptive.points.back().travel == Approx(loading.travel).epsilon(1e-12));
  const Real step = loading.travel / loading.increments;
  int compared = 0;
  Real largest_step = 0, previous = 0;
  for (const PathPoint& a : adaptive.points) {
    largest_step = std::max(largest_step, a.travel - previous);
    previous = a.travel;
    const long k = std::lround(a.travel / step);  // steps grow by doubling: multiples of the first
    REQUIRE(std::abs(a.travel - k * step) < 1e-9 * step);
    const PathPoint& f = fixed.points[size_t(k - 1)];
    CAPTURE(a.travel, f.travel);
    CHECK(a.load == Approx(f.load).epsilon(1e-7));
    CHECK(a.stable);
    ++compared;
  }
  CHECK(compared == int(adaptive.points.size()));
  CHECK(largest_step > 1.5 * step);
  CHECK(largest_step < 4 * step * (1 + 1e-9));
  // Every stability check of this stable path either factorised or was answered by a
  // positive definite true tangent of Newton's last step.
  CHECK(fixed.checks_from_newton > 0);
}

TEST_CASE("A Newton failure halves the step and the path goes on; only the smallest step's failure ends it", "[statics]") {
  // The cube compressed 40 % in two increments, Newton allowed 4 steps: a 20 % step from the
  // last equilibrium cannot converge in 4, shorter ones can. The path must reach the full
  // travel through the halved steps, and its equilibria must be the fixed 16-increment
  // path's (the same tolerance at the same travels: the path does not depend on the steps).
  const Real h = 1e-3, side = 4 * h;
  StaticProblem problem = test::neo_hookean_cube(h);
  NewtonOptions newton;
  newton.tolerance = 1e-10;
  SparseSolver solver(LinearSolverKind::cholmod);
  const PathReport reference = load_by_platen(problem, test::clamped_platens(problem, 4, 0.4 * side, 16), solver, newton);
  REQUIRE_FALSE(reference.ended);
  newton.max_iterations = 4;
  PlatenLoading loading = test::clamped_platens(problem, 4, 0.4 * side, 2);
  loading.bisections = 3;  // steps down to 40 % / 2 / 8 = 2.5 %: the reference's travels
  const PathReport cut = load_by_platen(problem, loading, solver, newton);
  CAPTURE(cut.end_reason, cut.end_travel, cut.cut_backs);
  REQUIRE_FALSE(cut.ended);
  CHECK(cut.cut_backs > 0);
  CHECK(cut.points.back().travel == Approx(loading.travel).epsilon(1e-12));
  const Real fine = loading.travel / 16;
  int compared = 0;
  for (const PathPoint& p : cut.points) {
    const long k = std::lround(p.travel / fine);  // halvings of the increment, at most three
    REQUIRE(std::abs(p.travel - k * fine) < 1e-9 * fine);
    CHECK(p.newton_iterations <= 3 * newton.max_iterations);  // predictor, restart, factorising
    CHECK(p.load == Approx(reference.points[size_t(k - 1)].load).epsilon(1e-7));
    ++compared;
  }
  CHECK(compared == int(cut.points.size()));

  // Newton allowed one step only converges nowhere (the platen's step needs equilibrium
  // iterations): the path ends after `bisections` halvings, bracketing the start.
  newton.max_iterations = 1;
  const PathReport none = load_by_platen(problem, loading, solver, newton);
  REQUIRE(none.ended);
  CHECK(none.points.empty());
  CHECK(none.cut_backs == loading.bisections);
  CHECK(none.end_travel == Approx(0.5 * std::ldexp(loading.travel / 2, -loading.bisections)).epsilon(1e-12));
  CHECK(none.end_load == 0);
}
