// An axially compressed neo-Hookean column between clamped ends, loaded by a platen in
// increments: its static path ends (the true tangent stops being positive definite) within
// 5 % of the Euler load of a clamped-clamped column, P = 4π² E I / L².
#include <catch2/catch.hpp>

#include <cmath>

#include "point_blocks.hpp"
#include "statics/displacement_control.hpp"

using namespace latmpm;
using namespace latmpm::statics;

TEST_CASE("A clamped column's static path ends at the Euler load", "[statics]") {
  const Real h = 1e-3, side = 4 * h, length = 60 * h, E = 1e7, nu = 0.3;
  const test::PointBlock block = test::point_block(Vec3::Zero(), Vec3(side, side, length), h, 2);
  StaticProblem problem = test::make_problem(block, h, mpm::ShapeFunctionKind::bspline2,
                                             test::material(mpm::MaterialKind::neo_hookean, E, nu));
  PlatenLoading loading = test::clamped_platens(problem, 60);
  const Real euler = 4 * M_PI * M_PI * E * (side * side * side * side / 12) / (length * length);
  const Real euler_travel = euler / (E * side * side) * length;
  loading.travel = 1.25 * euler_travel;
  loading.increments = 5;
  loading.bisections = 4;
  SparseSolver solver(LinearSolverKind::cholmod);
  const PathReport path = load_by_platen(problem, loading, solver);
  REQUIRE(path.ended);
  CHECK(path.end_reason == "tangent not positive definite");
  CAPTURE(path.end_load, path.last_stable_load, euler, path.end_travel, euler_travel);
  CHECK(path.end_load == Approx(euler).epsilon(0.05));
  CHECK(path.last_stable_load <= path.end_load);
  // Before the end the load rises with the travel (a stable, stiffening-free path).
  for (size_t i = 1; i < path.points.size(); ++i)
    if (path.points[i].stable) CHECK(path.points[i].load > path.points[i - 1].load);
}
