// The affine stabilisation (statics/affine_stabilisation.hpp): it leaves every nodal field
// that is affine on the stencils free (patch test, rigid motions), its forces and Hessian
// are the derivatives of its energy, it gives the point quadrature's zero-energy modes
// stiffness, and with it the true-tangent check finds the Euler load of a column only two
// cells thick, where without it the check fires at once.
#include <catch2/catch.hpp>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <random>

#include "point_blocks.hpp"
#include "statics/displacement_control.hpp"

using namespace latmpm;
using namespace latmpm::statics;

namespace {
const Real h = 1e-3;

Vector affine_field(const NarrowBand& band, const Mat3& A, const Vec3& b) {
  Vector u(Eigen::Index(3 * band.node_count()));
  for (size_t n = 0; n < band.node_count(); ++n) u.segment<3>(Eigen::Index(3 * n)) = A * band.node_position(n) + b;
  return u;
}

// Eigenvalues of the Hessian at u = 0 with the nodes at z ≤ 0 clamped (rows and columns
// removed), relative to the largest.
Eigen::VectorXd clamped_spectrum(StaticProblem& problem) {
  problem.assemble_hessian(Vector::Zero(Eigen::Index(problem.dof_count())), false);
  std::vector<Eigen::Index> free;
  for (size_t n = 0; n < problem.band().node_count(); ++n)
    if (problem.band().node[n][2] > 0)
      for (int a = 0; a < 3; ++a) free.push_back(Eigen::Index(3 * n + size_t(a)));
  const Eigen::MatrixXd K = Eigen::MatrixXd(problem.hessian());
  Eigen::MatrixXd Kf(free.size(), free.size());
  for (size_t i = 0; i < free.size(); ++i)
    for (size_t j = 0; j < free.size(); ++j) Kf(Eigen::Index(i), Eigen::Index(j)) = K(free[i], free[j]);
  const Eigen::VectorXd values = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Kf).eigenvalues();
  return values / values.maxCoeff();
}
}  // namespace

TEST_CASE("The affine stabilisation adds nothing for fields affine on the stencils", "[statics]") {
  const test::PointBlock block = test::point_block(Vec3::Zero(), Vec3(3 * h, 3 * h, 4 * h), h, 2);
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> r(-0.05, 0.05);
  for (auto shape : {mpm::ShapeFunctionKind::linear, mpm::ShapeFunctionKind::ugimp, mpm::ShapeFunctionKind::bspline2,
                     mpm::ShapeFunctionKind::bspline3}) {
    CAPTURE(mpm::to_string(shape));
    StaticProblem plain = test::make_problem(block, h, shape, test::material(mpm::MaterialKind::neo_hookean, 1e7, 0.3));
    StaticProblem stabilised = test::make_problem(block, h, shape, test::material(mpm::MaterialKind::neo_hookean, 1e7, 0.3));
    stabilised.set_stabilisation(0.1);
    Mat3 A;
    for (int i = 0; i < 9; ++i) A(i / 3, i % 3) = r(rng);
    const Vector u = affine_field(plain.band(), A, Vec3(r(rng), r(rng), r(rng)) * h);
    CHECK(stabilised.energy(u) == Approx(plain.energy(u)).epsilon(1e-12));
    const Vector df = stabilised.internal_force(u) - plain.internal_force(u);
    CHECK(df.norm() <= 1e-10 * plain.internal_force(u).norm());
    // A rigid rotation by 30° is affine too: no stabilisation energy, no stress.
    const Mat3 R = Eigen::AngleAxisd(M_PI / 6, Vec3(1, 2, 3).normalized()).toRotationMatrix();
    const Vector rotation = affine_field(plain.band(), R - Mat3::Identity(), Vec3::Zero());
    CHECK(std::abs(stabilised.energy(rotation)) <= 1e-12 * plain.energy(u));
  }
}

TEST_CASE("The stabilised force and Hessian are derivatives of the stabilised energy", "[statics]") {
  const test::PointBlock block = test::point_block(Vec3::Zero(), Vec3(2 * h, 3 * h, 3 * h), h, 2);
  StaticProblem problem = test::make_problem(block, h, mpm::ShapeFunctionKind::ugimp,
                                             test::material(mpm::MaterialKind::linear_elastic, 1e7, 0.3));
  problem.set_stabilisation(0.5);  // large, so that it dominates the check
  std::mt19937 rng(3);
  std::uniform_real_distribution<Real> r(-1, 1);
  Vector u(Eigen::Index(problem.dof_count())), d(u.size());
  for (Eigen::Index i = 0; i < u.size(); ++i) u[i] = 1e-5 * r(rng), d[i] = 1e-5 * r(rng);
  const Real eps = 1e-3;
  const Real dE = (problem.energy(u + eps * d) - problem.energy(u - eps * d)) / (2 * eps);
  CHECK(problem.internal_force(u).dot(d) == Approx(dE).epsilon(1e-6));
  problem.assemble_hessian(u, false);
  const Vector Hd = problem.hessian() * d;
  const Vector df = (problem.internal_force(u + eps * d) - problem.internal_force(u - eps * d)) / (2 * eps);
  CHECK((Hd - df).norm() <= 1e-6 * df.norm());
  const SparseMatrix H = problem.hessian();
  CHECK((Eigen::MatrixXd(H) - Eigen::MatrixXd(H).transpose()).norm() <= 1e-12 * Eigen::MatrixXd(H).norm());
}

TEST_CASE("The stabilisation gives a two-cell-thick bar's zero-energy modes stiffness", "[statics]") {
  // Quadratic B-splines, 2 points per cell: 5 nodes but 4 sample planes across each side.
  const test::PointBlock block = test::point_block(Vec3::Zero(), Vec3(2 * h, 2 * h, 4 * h), h, 2);
  auto material = test::material(mpm::MaterialKind::linear_elastic, 1e7, 0.3);
  StaticProblem problem = test::make_problem(block, h, mpm::ShapeFunctionKind::bspline2, material);
  const Eigen::VectorXd plain = clamped_spectrum(problem);
  problem.set_stabilisation(0.1);
  const Eigen::VectorXd stabilised = clamped_spectrum(problem);
  const auto zero_modes = [](const Eigen::VectorXd& v) { return (v.array() < 1e-10).count(); };
  CAPTURE(plain.head(4).transpose(), stabilised.head(4).transpose());
  CHECK(zero_modes(plain) > 0);
  CHECK(zero_modes(stabilised) == 0);
}

TEST_CASE("With the stabilisation a two-cell-thick column's static path ends at the Euler load", "[statics]") {
  // Clamped–clamped, 2×2 cells (2 mm) × 40 cells, quadratic B-splines, neo-Hookean.
  // β = 0.1 (docs/statics.md).
  const Real side = 2 * h, length = 40 * h, E = 1e7, nu = 0.3;
  const test::PointBlock block = test::point_block(Vec3::Zero(), Vec3(side, side, length), h, 2);
  const Real euler = 4 * M_PI * M_PI * E * (side * side * side * side / 12) / (length * length);
  const Real euler_travel = euler / (E * side * side) * length;
  for (const Real beta : {0.0, 0.1}) {
    CAPTURE(beta);
    StaticProblem problem = test::make_problem(block, h, mpm::ShapeFunctionKind::bspline2,
                                               test::material(mpm::MaterialKind::neo_hookean, E, nu));
    problem.set_stabilisation(beta);
    PlatenLoading loading = test::clamped_platens(problem, 40);
    loading.travel = 1.25 * euler_travel;
    loading.increments = 5;
    loading.bisections = 4;
    SparseSolver solver(LinearSolverKind::cholmod);
    const PathReport path = load_by_platen(problem, loading, solver);
    CAPTURE(path.end_reason, path.end_load, path.end_travel, euler, euler_travel);
    REQUIRE(path.ended);
    if (beta == 0) {
      CHECK(path.end_load < 0.2 * euler);  // the zero-energy modes end the path at once
      // (β = 0.01 and 0.03 end it at −7.5 % and −5.9 %: the stabilisation must outweigh the
      // compressive stress's negative geometric stiffness; β = 0.3 stiffens it to +16 %.)
    } else {
      CHECK(path.end_reason == "tangent not positive definite");
      CHECK(path.end_load == Approx(euler).epsilon(0.05));
    }
  }
}
