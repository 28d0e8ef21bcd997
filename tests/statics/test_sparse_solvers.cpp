// The sparse solvers give the same static solution, "auto" picks CHOLMOD for small
// problems, and the direct ones tell a positive definite tangent from an indefinite one.
#include <catch2/catch.hpp>

#include <memory>

#include "point_blocks.hpp"
#include "core/errors.hpp"
#include "statics/projected_newton.hpp"

using namespace latmpm;
using namespace latmpm::statics;

namespace {
// A 2×2×6-cell bar clamped at z ≤ 0 and pulled sideways at its top, linear elastic.
struct Bar {
  explicit Bar(const test::PointBlock& block, Real h)
      : problem(test::make_problem(block, h, mpm::ShapeFunctionKind::bspline2,
                                   test::material(mpm::MaterialKind::linear_elastic, 1e7, 0.3))),
        dirichlet(problem.dof_count()) {}
  StaticProblem problem;
  Dirichlet dirichlet;
};

std::unique_ptr<Bar> clamped_bar() {
  const Real h = 1e-3;
  const test::PointBlock block = test::point_block(Vec3::Zero(), Vec3(3 * h, 3 * h, 6 * h), h, 2);
  auto bar_ptr = std::make_unique<Bar>(block, h);
  Bar& bar = *bar_ptr;
  for (size_t n = 0; n < bar.problem.band().node_count(); ++n)
    if (bar.problem.band().node[n][2] <= 0) bar.dirichlet.prescribe(n, Vec3::Zero());
  std::vector<Vec3> force(block.position.size(), Vec3::Zero());
  for (size_t p = 0; p < force.size(); ++p)
    if (block.position[p][2] > 5.5 * h) force[p] = Vec3(1e-2, 0, 0);
  bar.problem.set_point_forces(force);
  return bar_ptr;
}
}  // namespace

TEST_CASE("LDLT, CG, CHOLMOD and hypre's AMG give the same displacements", "[statics]") {
  const auto owner = clamped_bar();
  Bar& bar = *owner;
  std::vector<Vector> solutions;
  for (LinearSolverKind kind :
       {LinearSolverKind::ldlt, LinearSolverKind::cg, LinearSolverKind::cholmod, LinearSolverKind::amg}) {
    CAPTURE(to_string(kind));
    Vector u = Vector::Zero(Eigen::Index(bar.problem.dof_count()));
    SparseSolver solver(kind, 1e-12);
    std::vector<Vec3> nodes;
    for (size_t n = 0; n < bar.problem.band().node_count(); ++n) nodes.push_back(bar.problem.band().node_position(n));
    solver.set_node_positions(nodes);
    const NewtonReport report = solve_equilibrium(bar.problem, bar.dirichlet, u, solver);
    CAPTURE(report.failure, report.residual, report.linear_iterations);
    REQUIRE(report.converged);
    CHECK(report.iterations == 1);
    CHECK(report.linear_residual <= 1e-10);
    if (kind == LinearSolverKind::cg || kind == LinearSolverKind::amg) CHECK(report.linear_iterations > 1);
    if (kind == LinearSolverKind::amg) CHECK_THAT(solver.describe(), Catch::Contains("3 rigid-body rotations"));
    solutions.push_back(u);
  }
  CHECK((solutions[1] - solutions[0]).norm() <= 1e-8 * solutions[0].norm());
  CHECK((solutions[2] - solutions[0]).norm() <= 1e-10 * solutions[0].norm());
  CHECK((solutions[3] - solutions[0]).norm() <= 1e-8 * solutions[0].norm());
}

TEST_CASE("The automatic choice takes CHOLMOD unless its factor exceeds the memory budget", "[statics]") {
  const auto owner = clamped_bar();
  Bar& bar = *owner;
  for (const double budget : {1e9, 1e3}) {  // bytes: the bar's L needs ~1e5
    CAPTURE(budget);
    Vector u = Vector::Zero(Eigen::Index(bar.problem.dof_count()));
    SparseSolver solver(parse_linear_solver("auto"), 1e-12);
    solver.set_factor_memory_budget(budget);
    REQUIRE(solve_equilibrium(bar.problem, bar.dirichlet, u, solver).converged);
    CHECK_THAT(solver.describe(), Catch::StartsWith(budget > 1e6 ? "auto: cholmod" : "auto: amg"));
  }
  CHECK_THROWS_AS(parse_linear_solver("multigrid", "scene.toml", "solver.linear_solver"), InputError);
}

TEST_CASE("The direct solvers report an indefinite matrix as not positive definite", "[statics]") {
  const auto owner = clamped_bar();
  Bar& bar = *owner;
  bar.problem.assemble_hessian(Vector::Zero(Eigen::Index(bar.problem.dof_count())), false);
  SparseMatrix K = bar.problem.hessian();
  constrain_rows_and_columns(K, bar.dirichlet.fixed, mean_diagonal(K));
  for (LinearSolverKind kind : {LinearSolverKind::ldlt, LinearSolverKind::cholmod}) {
    CAPTURE(to_string(kind));
    SparseSolver solver(kind);
    CHECK(solver.factorize(K));
    SparseMatrix shifted = K;
    for (int i = 0; i < 3; ++i) shifted.coeffRef(i + 300, i + 300) = -1;  // a negative pivot
    SparseSolver fresh(kind);
    CHECK_FALSE(fresh.factorize(shifted));
  }
}
