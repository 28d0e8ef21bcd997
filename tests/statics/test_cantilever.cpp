// A cantilever with a tip load against Timoshenko beam theory: deflection
//   δ = F L³ / (3 E I) + F L / (κ G A),  κ = 10(1+ν)/(12+11ν) (Cowper, rectangle),
// with 8 cells across the depth and quadratic B-splines (paper C's shape function).
// Linear elasticity: one Newton step.
#include <catch2/catch.hpp>

#include <cmath>

#include "point_blocks.hpp"
#include "statics/projected_newton.hpp"

using namespace latmpm;
using namespace latmpm::statics;

TEST_CASE("A tip-loaded cantilever deflects as Timoshenko's beam within 2 %", "[statics]") {
  const Real h = 1e-3, depth = 8 * h, width = 4 * h, length = 80 * h;
  const Real E = 1e7, nu = 0.3, load = 0.5;  // Pa, −, N
  const int ppc = 2;
  const test::PointBlock block = test::point_block(Vec3::Zero(), Vec3(length, width, depth), h, ppc);
  StaticProblem problem = test::make_problem(block, h, mpm::ShapeFunctionKind::bspline2,
                                             test::material(mpm::MaterialKind::linear_elastic, E, nu));
  // Clamped: every node at or behind the clamped face x = 0.
  Dirichlet dirichlet(problem.dof_count());
  for (size_t n = 0; n < problem.band().node_count(); ++n)
    if (problem.band().node[n][0] <= 0) dirichlet.prescribe(n, Vec3::Zero());
  // The load spread over the last layer of points.
  const Real tip = length - h / (2 * ppc);
  std::vector<size_t> tip_points;
  for (size_t p = 0; p < block.position.size(); ++p)
    if (block.position[p][0] > tip - 1e-9) tip_points.push_back(p);
  std::vector<Vec3> force(block.position.size(), Vec3::Zero());
  for (size_t p : tip_points) force[p] = Vec3(0, 0, -load / Real(tip_points.size()));
  problem.set_point_forces(force);

  // Mean deflection of the tip points, from the nodes through their weights.
  auto tip_deflection = [&]() {
    Vector u = Vector::Zero(Eigen::Index(problem.dof_count()));
    SparseSolver solver(LinearSolverKind::cholmod);
    const NewtonReport report = solve_equilibrium(problem, dirichlet, u, solver);
    REQUIRE(report.converged);
    CHECK(report.iterations == 1);
    Real sum = 0;
    const NarrowBand& band = problem.band();
    for (size_t p : tip_points)
      for (uint32_t e = band.point_offset[p]; e < band.point_offset[p + 1]; ++e)
        sum -= band.entry_weight[e] * u[Eigen::Index(3 * band.entry_node[e] + 2)];
    return sum / Real(tip_points.size());
  };
  const Real deflection = tip_deflection();
  problem.set_stabilisation(0.1);  // the affine stabilisation stiffens bending a little
  const Real stabilised = tip_deflection();

  const Real I = width * depth * depth * depth / 12, A = width * depth, G = E / (2 * (1 + nu));
  const Real kappa = 10 * (1 + nu) / (12 + 11 * nu);
  const Real expected = load * tip * tip * tip / (3 * E * I) + load * tip / (kappa * G * A);
  CAPTURE(deflection, stabilised, expected);
  CHECK(deflection == Approx(expected).epsilon(0.02));
  CHECK(stabilised == Approx(expected).epsilon(0.02));
  CHECK(std::abs(stabilised / deflection - 1) < 0.01);  // measured: −0.6 %
}
