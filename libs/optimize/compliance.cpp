#include "optimize/compliance.hpp"

#include <cmath>

#include "core/errors.hpp"
#include "statics/projected_newton.hpp"

namespace latmpm::optimize {

Real SimpMaterial::modulus(Real rho) const {
  const Real Emin = weak_ratio * young_modulus;
  return Emin + std::pow(rho, penalty) * (young_modulus - Emin);
}

Real SimpMaterial::modulus_derivative(Real rho) const {
  const Real Emin = weak_ratio * young_modulus;
  return penalty * std::pow(rho, penalty - 1) * (young_modulus - Emin);
}

ComplianceResult evaluate_compliance(const DesignGrid& grid, const std::vector<Real>& density,
                                     const std::vector<char>& active, const LoadCase& load_case,
                                     const SimpMaterial& material) {
  using namespace latmpm::statics;
  const size_t n = grid.point_count();
  const Real V = grid.point_volume();
  std::vector<size_t> point_of;  // solver point -> quadrature point
  std::vector<Vec3> X, half;
  std::vector<Real> volume;
  for (size_t q = 0; q < n; ++q) {
    if (!active[q]) continue;
    point_of.push_back(q);
    X.push_back(grid.position(q));
    half.push_back(Vec3::Constant(grid.spacing() / 2));
    // ψ is linear in E for linear elasticity: E_q/E scales the point's volume (Eq. 25).
    volume.push_back(V * material.modulus(density[q]) / material.young_modulus);
  }
  if (X.empty()) throw NumericalError("compliance: no active quadrature point");

  mpm::MaterialParameters solid;
  solid.kind = mpm::MaterialKind::linear_elastic;
  solid.young_modulus = material.young_modulus;
  solid.poisson_ratio = material.poisson_ratio;
  const ElasticEnergy energy = ElasticEnergy::from(solid);
  StaticProblem problem(build_narrow_band(X, half, grid.cell_size, mpm::ShapeFunctionKind::linear), volume,
                        std::vector<uint16_t>(X.size(), 0), {energy});

  std::vector<Vec3> force(X.size(), Vec3::Zero());
  std::vector<long> solver_point(n, -1);
  for (size_t p = 0; p < point_of.size(); ++p) solver_point[point_of[p]] = long(p);
  const auto loaded = loaded_points(grid, load_case);
  for (size_t l = 0; l < loaded.size(); ++l)
    for (size_t q : loaded[l]) {
      if (solver_point[q] < 0) throw NumericalError("compliance: load '" + load_case.loads[l].name + "' acts on an inactive point");
      force[size_t(solver_point[q])] += load_case.loads[l].force / Real(loaded[l].size());
    }
  problem.set_point_forces(force);

  const NarrowBand& band = problem.band();
  Dirichlet dirichlet(problem.dof_count());
  for (size_t node = 0; node < band.node_count(); ++node) {
    const Vec3 x = band.node_position(node);
    for (const Support& s : load_case.supports)
      if (s.box.contains(x))
        for (int a = 0; a < 3; ++a)
          if (s.held[size_t(a)]) dirichlet.fixed[3 * node + size_t(a)] = 1;
    if (grid.planar) dirichlet.fixed[3 * node + 2] = 1;  // plane strain
  }

  Vector u = Vector::Zero(Eigen::Index(problem.dof_count()));
  SparseSolver solver(LinearSolverKind::cholmod);
  // Linear elasticity: one Newton step solves it; the projected Newton's diagonal shift
  // (docs/statics.md) holds a part the band leaves unsupported, whose residual then stays
  // at the shift's level: accepted up to 1e-4 (its huge compliance steers the optimiser
  // back), anything worse is a failure.
  NewtonOptions options;
  options.max_iterations = 10;  // iterative refinement where E_min = 1e-9 E makes K ill-conditioned
  const NewtonReport report = solve_equilibrium(problem, dirichlet, u, solver, options);
  if (!report.converged && !(report.iterations > 0 && report.residual.back() <= 1e-4))
    throw NumericalError("compliance: static solve failed: " + report.failure);

  ComplianceResult r;
  r.gradient.assign(n, 0);
  r.point_displacement.assign(n, Vec3::Zero());
  r.active_points = X.size();
  r.unknowns = problem.dof_count() - dirichlet.count();
  r.external_work = 0.5 * problem.external_force().dot(u);
  const std::vector<Mat3> F = problem.deformation_gradients(u);
  for (size_t p = 0; p < X.size(); ++p) {
    const size_t q = point_of[p];
    const Real psi = energy.density(F[p]);  // ψ(F_q; E), J/m³
    r.compliance += volume[p] * psi;
    r.gradient[q] = -V * material.modulus_derivative(density[q]) / material.young_modulus * psi;
    Vec3 up = Vec3::Zero();
    for (uint32_t e = band.point_offset[p]; e < band.point_offset[p + 1]; ++e)
      up += band.entry_weight[e] * u.segment<3>(Eigen::Index(3 * band.entry_node[e]));
    r.point_displacement[q] = up;
  }
  return r;
}

}  // namespace latmpm::optimize
