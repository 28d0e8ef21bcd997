// The discrete problem's derivatives against finite differences: the internal force is
// the gradient of the energy, and the assembled (unprojected) Hessian its derivative.
#include <catch2/catch.hpp>

#include <random>

#include "point_blocks.hpp"

using namespace latmpm;
using namespace latmpm::statics;

TEST_CASE("The internal force and the assembled Hessian are derivatives of the energy", "[statics]") {
  const auto shape = GENERATE(mpm::ShapeFunctionKind::linear, mpm::ShapeFunctionKind::bspline2);
  const auto kind = GENERATE(mpm::MaterialKind::linear_elastic, mpm::MaterialKind::neo_hookean);
  CAPTURE(mpm::to_string(shape), mpm::to_string(kind));
  const Real h = 1e-3;
  const test::PointBlock block = test::point_block(Vec3::Zero(), Vec3(2 * h, 3 * h, 2 * h), h, 2);
  StaticProblem problem = test::make_problem(block, h, shape, test::material(kind, 1e7, 0.3));
  std::mt19937 rng(3);
  std::uniform_real_distribution<Real> uniform(-1, 1);
  Vector u(Eigen::Index(problem.dof_count())), d(u.size());
  for (Eigen::Index i = 0; i < u.size(); ++i) u[i] = 2e-5 * uniform(rng), d[i] = 1e-5 * uniform(rng);
  REQUIRE(problem.min_jacobian(u) > 0.5);
  const Real eps = 1e-4;
  const Vector f = problem.internal_force(u);
  const Real dE = (problem.energy(u + eps * d) - problem.energy(u - eps * d)) / (2 * eps);
  CHECK(dE == Approx(f.dot(d)).epsilon(1e-6));
  problem.assemble_hessian(u, false);
  const Vector Hd = problem.hessian() * d;
  const Vector df = (problem.internal_force(u + eps * d) - problem.internal_force(u - eps * d)) / (2 * eps);
  CHECK((Hd - df).norm() <= 1e-6 * df.norm());
  // Symmetric storage.
  const SparseMatrix H = problem.hessian();
  CHECK((SparseMatrix(H.transpose()) - H).norm() <= 1e-12 * H.norm());
}
