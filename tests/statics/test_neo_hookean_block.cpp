// A neo-Hookean block compressed to half its height between clamped platens: every load
// increment converges with no inverted point, the energy decreases monotonically over the
// Newton steps after the platen has moved, and convergence is quadratic near the solution.
#include <catch2/catch.hpp>

#include <cmath>

#include "point_blocks.hpp"
#include "statics/projected_newton.hpp"

using namespace latmpm;
using namespace latmpm::statics;

TEST_CASE("A neo-Hookean block compressed to 50 % never inverts and converges quadratically", "[statics]") {
  const Real h = 1e-3, side = 4 * h;
  StaticProblem problem = test::neo_hookean_cube(h);
  const int increments = 10;
  Vector u = Vector::Zero(Eigen::Index(problem.dof_count()));
  SparseSolver solver(LinearSolverKind::cholmod);
  NewtonOptions options;
  options.tolerance = 1e-10;
  int quadratic_steps = 0;
  for (int i = 1; i <= increments; ++i) {
    Dirichlet dirichlet(problem.dof_count());
    for (size_t n = 0; n < problem.band().node_count(); ++n) {
      const int k = problem.band().node[n][2];
      if (k <= 0) dirichlet.prescribe(n, Vec3::Zero());
      if (k >= 4) dirichlet.prescribe(n, Vec3(0, 0, -0.5 * side * i / increments));
    }
    const NewtonReport report = solve_equilibrium(problem, dirichlet, u, solver, options);
    CAPTURE(i, report.failure);
    REQUIRE(report.converged);
    CHECK(report.min_jacobian > 0);
    // The first step moves the platen; from there on the energy never rises.
    for (size_t k = 2; k < report.energy.size(); ++k)
      CHECK(report.energy[k] <= report.energy[k - 1] * (1 + 1e-12));
    for (size_t k = 1; k + 1 < report.residual.size(); ++k)
      if (report.residual[k] < 1e-3 && report.residual[k + 1] > 1e-14) {
        CHECK(report.residual[k + 1] <= 10 * report.residual[k] * report.residual[k] + 1e-13);
        ++quadratic_steps;
      }
    if (i == increments) {
      INFO("residual history of the last increment:");
      for (Real r : report.residual) UNSCOPED_INFO(r);
    }
  }
  CHECK(quadratic_steps >= increments / 2);
  CHECK(problem.min_jacobian(u) > 0);
}
