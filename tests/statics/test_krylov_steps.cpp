// Krylov steps (projected_newton.hpp, NewtonOptions::krylov_iterations): CG preconditioned by
// the Cholesky factor of an earlier matrix (preconditioned_cg.hpp). The preconditioned
// solve must reach its tolerance on a nearby matrix and refuse without a factor; a path
// solved with Krylov steps must reach the same equilibria (each increment is solved to the
// same residual tolerance) with fewer factorisations, and the stability checks must still
// be made by factorisation.
#include <catch2/catch.hpp>

#include "point_blocks.hpp"
#include "statics/displacement_control.hpp"

using namespace latmpm;
using namespace latmpm::statics;

TEST_CASE("CG preconditioned by an earlier factor solves a nearby matrix to its tolerance", "[statics]") {
  const Real h = 1e-3;
  StaticProblem problem = test::neo_hookean_cube(h);
  const Vector u0 = Vector::Zero(Eigen::Index(problem.dof_count()));
  problem.assemble_hessian(u0, true);
  SparseMatrix K0 = problem.hessian();
  for (Eigen::Index i = 0; i < K0.rows(); ++i) K0.coeffRef(i, i) += 1e-2 * mean_diagonal(K0);  // no rigid modes
  SparseSolver solver(LinearSolverKind::cholmod);
  const Vector b = Vector::LinSpaced(K0.rows(), -1, 2);
  Vector x;
  CHECK(solver.solve_preconditioned(K0, b, 1e-10, 50, x).outcome == KrylovOutcome::not_converged);  // no factor yet
  REQUIRE(solver.factorize(K0));
  CHECK(solver.has_factor());
  // The tangent of a uniformly compressed state: another matrix, close to K0.
  Vector u = Vector::Zero(Eigen::Index(problem.dof_count()));
  for (size_t n = 0; n < problem.band().node_count(); ++n)
    u[Eigen::Index(3 * n + 2)] = -0.05 * problem.band().node_position(n)[2];
  problem.assemble_hessian(u, true);
  SparseMatrix K1 = problem.hessian();
  for (Eigen::Index i = 0; i < K1.rows(); ++i) K1.coeffRef(i, i) += 1e-2 * mean_diagonal(K1);
  REQUIRE((K1 - K0).norm() > 1e-3 * K0.norm());
  const KrylovResult r = solver.solve_preconditioned(K1, b, 1e-10, 50, x);
  REQUIRE(r.outcome == KrylovOutcome::solved);
  CHECK((K1 * x - b).norm() <= 1e-10 * b.norm());
  CHECK(r.relative_residual == Approx((K1 * x - b).norm() / b.norm()));
  CHECK(r.iterations > 1);
  CHECK(r.iterations < 50);
  // Too few iterations: refused, not a half-solved answer.
  CHECK(solver.solve_preconditioned(K1, b, 1e-14, 1, x).outcome == KrylovOutcome::not_converged);
  // An indefinite matrix (one negative pivot direction along b): non-positive curvature.
  SparseMatrix K2 = K1;
  for (Eigen::Index i = 0; i < K2.rows(); ++i) K2.coeffRef(i, i) -= 10 * K1.coeffRef(i, i);
  CHECK(solver.solve_preconditioned(K2, b, 1e-10, 50, x).outcome == KrylovOutcome::negative_curvature);
}

TEST_CASE("Krylov steps follow the factorising path with fewer factorisations", "[statics]") {
  const Real h = 1e-3, side = 4 * h;
  StaticProblem problem = test::neo_hookean_cube(h);
  PlatenLoading loading = test::clamped_platens(problem, 4, 0.4 * side, 8);
  NewtonOptions newton;
  newton.tolerance = 1e-10;
  auto run = [&](int krylov, int& factorisations) {
    newton.krylov_iterations = krylov;
    SparseSolver solver(LinearSolverKind::cholmod);
    const PathReport r = load_by_platen(problem, loading, solver, newton);
    factorisations = solver.times().factorise.calls;
    return r;
  };
  int factorised_plain = 0, factorised_krylov = 0;
  const PathReport plain = run(0, factorised_plain), krylov = run(20, factorised_krylov);
  REQUIRE_FALSE(plain.ended);
  REQUIRE_FALSE(krylov.ended);
  REQUIRE(plain.points.size() == krylov.points.size());
  int krylov_steps = 0;
  for (size_t i = 0; i < plain.points.size(); ++i) {
    CAPTURE(i);
    CHECK(krylov.points[i].travel == plain.points[i].travel);
    CHECK(krylov.points[i].load == Approx(plain.points[i].load).epsilon(1e-7));
    CHECK(krylov.points[i].residual <= newton.tolerance);
    CHECK(krylov.points[i].stable);
    CHECK(plain.points[i].krylov_steps == 0);
    krylov_steps += krylov.points[i].krylov_steps;
  }
  CAPTURE(factorised_plain, factorised_krylov, krylov_steps);
  CHECK(krylov_steps > 0);
  CHECK(factorised_krylov < factorised_plain);
  // A Krylov step says nothing of definiteness: every increment ending with one is checked
  // by a factorisation of its own.
  CHECK(krylov.checks_from_newton < plain.checks_from_newton);
}
