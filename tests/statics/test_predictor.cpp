// The secant predictor of displacement-controlled loading (displacement_control.hpp): a
// neo-Hookean block compressed to 60 % of its height between clamped platens follows the
// same path with and without it (each increment is solved to the same tolerance, so the
// equilibria agree whatever the start), in fewer Newton steps with it.
#include <catch2/catch.hpp>

#include "point_blocks.hpp"
#include "statics/displacement_control.hpp"

using namespace latmpm;
using namespace latmpm::statics;

TEST_CASE("The secant predictor saves Newton steps without changing the static path", "[statics]") {
  const Real h = 1e-3, side = 4 * h;
  StaticProblem problem = test::neo_hookean_cube(h);
  PlatenLoading loading = test::clamped_platens(problem, 4);
  loading.travel = 0.4 * side;
  loading.increments = 8;
  loading.check_stability = false;
  NewtonOptions newton;
  newton.tolerance = 1e-10;
  auto run = [&](bool predictor) {
    loading.predictor = predictor;
    SparseSolver solver(LinearSolverKind::cholmod);
    return load_by_platen(problem, loading, solver, newton);
  };
  const PathReport plain = run(false), predicted = run(true);
  REQUIRE_FALSE(plain.ended);
  REQUIRE_FALSE(predicted.ended);
  REQUIRE(plain.points.size() == predicted.points.size());
  int steps_plain = 0, steps_predicted = 0;
  for (size_t i = 0; i < plain.points.size(); ++i) {
    CAPTURE(i);
    CHECK(predicted.points[i].travel == plain.points[i].travel);
    CHECK(predicted.points[i].load == Approx(plain.points[i].load).epsilon(1e-7));
    CHECK(predicted.points[i].predicted == (i >= 1));  // from the second increment on
    CHECK_FALSE(plain.points[i].predicted);
    steps_plain += plain.points[i].newton_iterations;
    steps_predicted += predicted.points[i].newton_iterations;
  }
  CAPTURE(steps_plain, steps_predicted);
  CHECK(steps_predicted < steps_plain);
}
