// Patch test: nodes whose support is not filled with material take u = G x; the free
// interior must then reproduce the uniform strain F = I + G at every point to round-off,
// for every shape function and both energies. Linear elasticity takes one Newton step.
#include <catch2/catch.hpp>

#include "point_blocks.hpp"
#include "statics/projected_newton.hpp"

using namespace latmpm;
using namespace latmpm::statics;

namespace {
// Half-width of a node's support, m (uGIMP/cpGIMP: h + particle half-size h/(2 ppc)).
Real support_radius(mpm::ShapeFunctionKind shape, Real h, int ppc) {
  switch (shape) {
    case mpm::ShapeFunctionKind::linear: return h;
    case mpm::ShapeFunctionKind::bspline2: return 1.5 * h;
    case mpm::ShapeFunctionKind::bspline3: return 2 * h;
    default: return h + h / (2 * ppc);
  }
}
}  // namespace

TEST_CASE("A uniform strain is reproduced to round-off by every shape function", "[statics]") {
  const auto shape = GENERATE(mpm::ShapeFunctionKind::linear, mpm::ShapeFunctionKind::ugimp,
                              mpm::ShapeFunctionKind::cpgimp, mpm::ShapeFunctionKind::bspline2,
                              mpm::ShapeFunctionKind::bspline3);
  const auto kind = GENERATE(mpm::MaterialKind::linear_elastic, mpm::MaterialKind::neo_hookean);
  CAPTURE(mpm::to_string(shape), mpm::to_string(kind));
  const Real h = 1e-3;
  const int ppc = 2;
  const Vec3 lo = Vec3::Zero(), hi = Vec3::Constant(6 * h);
  const test::PointBlock block = test::point_block(lo, hi, h, ppc);
  StaticProblem problem = test::make_problem(block, h, shape, test::material(kind, 10e6, 0.3));
  Mat3 G;
  G << 0.02, -0.01, 0.005, 0.015, -0.03, 0.01, -0.005, 0.02, 0.01;

  const Real r = support_radius(shape, h, ppc);
  Dirichlet dirichlet(problem.dof_count());
  size_t free_nodes = 0;
  for (size_t n = 0; n < problem.band().node_count(); ++n) {
    const Vec3 x = problem.band().node_position(n);
    const bool inside = ((x.array() - r).minCoeff() >= -1e-12 * h) && ((x.array() + r).maxCoeff() <= 6 * h * (1 + 1e-12));
    if (inside) ++free_nodes;
    else dirichlet.prescribe(n, G * x);
  }
  REQUIRE(free_nodes >= 27);

  Vector u = Vector::Zero(Eigen::Index(problem.dof_count()));
  SparseSolver solver(LinearSolverKind::ldlt);
  const NewtonReport report = solve_equilibrium(problem, dirichlet, u, solver);
  CAPTURE(report.failure, report.iterations, report.residual);
  REQUIRE(report.converged);
  if (kind == mpm::MaterialKind::linear_elastic) CHECK(report.iterations == 1);
  Real worst = 0;
  for (const Mat3& F : problem.deformation_gradients(u)) worst = std::max(worst, (F - Mat3::Identity() - G).norm());
  CHECK(worst <= 1e-12);
  for (size_t n = 0; n < problem.band().node_count(); ++n)
    CHECK((u.segment<3>(Eigen::Index(3 * n)) - G * problem.band().node_position(n)).norm() <= 1e-13);
}
