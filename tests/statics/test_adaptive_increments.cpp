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
