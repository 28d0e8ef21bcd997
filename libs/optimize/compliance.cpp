#include "optimize/compliance.hpp"

#include <cmath>

#include "core/errors.hpp"
#include "statics/load_continuation.hpp"
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

namespace {

using namespace latmpm::statics;

constexpr Real neo_hookean_stabilisation = 0.1;  // β (× μ), docs/statics.md

// The adjoint of Eq. (19) for a nonlinear energy: K_T(u) λ = f on the free unknowns (λ = 0
// where prescribed), K_T the true (unprojected) tangent at equilibrium.
Vector adjoint_displacement(StaticProblem& problem, const Dirichlet& dirichlet, const Vector& u, SparseSolver& solver) {
  problem.assemble_hessian(u, false);
  SparseMatrix& K = problem.hessian();
  constrain_rows_and_columns(K, dirichlet.fixed, mean_diagonal(K));
  Vector rhs = problem.external_force();
  for (size_t i = 0; i < dirichlet.fixed.size(); ++i)
    if (dirichlet.fixed[i]) rhs[Eigen::Index(i)] = 0;
  if (!solver.factorize(K))
    throw NumericalError("compliance: the tangent at equilibrium is not positive definite (a buckled design): no adjoint");
  LinearSolveStats stats;
  return solver.solve(rhs, stats);
}

// Point p's affine stabilisation terms (statics/affine_stabilisation.hpp): with
// r_k(v) = v_k − v(X_p) − (Σ_j v_j ⊗ ∇S_jp)(X_k − X_p) over its n_p stencil nodes, the
// means (1/n_p) Σ_k |r_k(u)|² and (1/n_p) Σ_k r_k(u)·r_k(λ): E_s,p = c_p/2 × the first,
// λ · ∂E_s,p/∂u = c_p × the second.
struct AffineDepartures {
  Real uu = 0, ul = 0;
};

AffineDepartures affine_departures(const NarrowBand& band, size_t p, const Vector& u, const Vector& l) {
  const uint32_t first = band.point_offset[p], last = band.point_offset[p + 1];
  const Eigen::Vector3i& origin = band.node[band.entry_node[first]];
  auto position = [&](uint32_t e) -> Vec3 { return band.cell_size * (band.node[band.entry_node[e]] - origin).cast<Real>(); };
  auto at = [&](const Vector& v, uint32_t e) -> Vec3 { return v.segment<3>(Eigen::Index(3 * band.entry_node[e])); };
  Vec3 Xp = Vec3::Zero(), up = Vec3::Zero(), lp = Vec3::Zero();
  Mat3 Gu = Mat3::Zero(), Gl = Mat3::Zero();
  for (uint32_t e = first; e < last; ++e) {
    Xp += band.entry_weight[e] * position(e);
    up += band.entry_weight[e] * at(u, e);
    lp += band.entry_weight[e] * at(l, e);
    Gu += at(u, e) * band.entry_gradient[e].transpose();
    Gl += at(l, e) * band.entry_gradient[e].transpose();
  }
  AffineDepartures d;
  for (uint32_t e = first; e < last; ++e) {
    const Vec3 dx = position(e) - Xp;
    const Vec3 ru = at(u, e) - up - Gu * dx, rl = at(l, e) - lp - Gl * dx;
    d.uu += ru.squaredNorm();
    d.ul += ru.dot(rl);
  }
  const Real n = Real(last - first);
  d.uu /= n;
  d.ul /= n;
  return d;
}

// The guess on the band's nodes: a node the guess lacks (the band grew) takes the mean of
// its neighbours (26-neighbourhood) that have a value, in passes outward from the guess.
Vector guessed_displacement(const NarrowBand& band, const EquilibriumGuess& guess) {
  Vector u = Vector::Zero(Eigen::Index(3 * band.node_count()));
  std::vector<char> known(band.node_count(), 0);
  for (size_t node = 0; node < band.node_count(); ++node) {
    const Eigen::Vector3i& c = band.node[node];
    const auto it = guess.node_displacement.find(EquilibriumGuess::key(c[0], c[1], c[2]));
    if (it == guess.node_displacement.end()) continue;
    u.segment<3>(Eigen::Index(3 * node)) = it->second;
    known[node] = 1;
  }
  for (bool grew = true; grew;) {
    grew = false;
    std::vector<char> next = known;
    for (size_t node = 0; node < band.node_count(); ++node) {
      if (known[node]) continue;
      Vec3 sum = Vec3::Zero();
      int count = 0;
      for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const long m = band.find(band.node[node] + Eigen::Vector3i(dx, dy, dz));
            if (m < 0 || !known[size_t(m)]) continue;
            sum += u.segment<3>(Eigen::Index(3 * m));
            ++count;
          }
      if (count == 0) continue;
      u.segment<3>(Eigen::Index(3 * node)) = sum / Real(count);
      next[node] = 1;
      grew = true;
    }
    known.swap(next);
  }
  return u;
}

}  // namespace

ComplianceResult evaluate_compliance(const DesignGrid& grid, const std::vector<Real>& density,
                                     const std::vector<char>& active, const LoadCase& load_case,
                                     const SimpMaterial& material, EquilibriumGuess* guess) {
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
    // ψ is linear in E (linear elastic and neo-Hookean alike, ν fixed): E_q/E scales the
    // point's volume (Eq. 25).
    volume.push_back(V * material.modulus(density[q]) / material.young_modulus);
  }
  if (X.empty()) throw NumericalError("compliance: no active quadrature point");

  mpm::MaterialParameters solid;
  solid.kind = material.model;
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
  // back), anything worse is a failure. Neo-Hookean: projected Newton to a tight tolerance
  // (the adjoint below assumes equilibrium; where densities span six orders of magnitude
  // round-off stalls the residual near 1e-9, accepted up to 1e-8), from the guess under the
  // whole load, else by adaptive load continuation from rest.
  const bool linear = problem.is_quadratic();
  // Neo-Hookean: the affine stabilisation of the point quadrature's zero-energy modes
  // (β = 0.1 × μ_q, latmpm-solve's static default, docs/statics.md): a band cell holding
  // one or two design points has hourglass modes that the linear solve's diagonal shift
  // holds but that leave the nonlinear equilibrium without a solution. Its energy
  // c_q/2 (1/n) Σ|r_k|², c_q = β μ V_q / h² ∝ E_q, is part of C and of its gradient.
  const Real beta = linear ? 0 : neo_hookean_stabilisation;
  problem.set_stabilisation(beta);
  LoadContinuation continuation;
  continuation.newton.max_iterations = linear ? 10 : 30;  // linear: iterative refinement where E_min = 1e-9 E makes K ill-conditioned
  if (!linear) continuation.newton.tolerance = 1e-11;
  continuation.accepted = linear ? 1e-4 : 1e-8;
  if (linear) continuation.first_step = 1, continuation.max_increments = 1;
  if (!linear && guess) {
    u = guessed_displacement(band, *guess);
    for (size_t i = 0; i < dirichlet.fixed.size(); ++i)
      if (dirichlet.fixed[i]) u[Eigen::Index(i)] = dirichlet.value[Eigen::Index(i)];
  }
  const ContinuationReport report = solve_by_load_continuation(problem, dirichlet, force, u, solver, continuation);
  if (!report.converged)
    throw NumericalError("compliance: static solve failed: " + report.failure);
  if (!linear && guess) {
    guess->node_displacement.clear();
    for (size_t node = 0; node < band.node_count(); ++node) {
      const Eigen::Vector3i& c = band.node[node];
      guess->node_displacement[EquilibriumGuess::key(c[0], c[1], c[2])] = u.segment<3>(Eigen::Index(3 * node));
    }
  }
  const Vector adjoint = linear ? u : adjoint_displacement(problem, dirichlet, u, solver);

  ComplianceResult r;
  r.gradient.assign(n, 0);
  r.point_displacement.assign(n, Vec3::Zero());
  r.active_points = X.size();
  r.unknowns = problem.dof_count() - dirichlet.count();
  r.newton_iterations = report.newton_iterations;
  r.load_steps = report.steps;
  r.from_guess = report.from_start;
  r.external_work = 0.5 * problem.external_force().dot(u);
  const std::vector<Mat3> F = problem.deformation_gradients(u);
  for (size_t p = 0; p < X.size(); ++p) {
    const size_t q = point_of[p];
    const Real psi = energy.density(F[p]);  // ψ(F_q; E), J/m³
    r.compliance += volume[p] * psi;
    // P : ∇λ_q (= 2ψ for linear elasticity, where λ = u).
    const Real work = linear ? 2 * psi
                             : (energy.first_piola(F[p]).array() *
                                (problem.deformation_gradient(p, adjoint) - Mat3::Identity()).array()).sum();
    r.gradient[q] = V * material.modulus_derivative(density[q]) / material.young_modulus * (psi - work);
    if (beta > 0) {  // c_q = c̄ E_q/E with c̄ = β μ V / h²
      const Real cbar = beta * energy.mu * V / (grid.cell_size * grid.cell_size);
      const AffineDepartures d = affine_departures(band, p, u, adjoint);
      r.compliance += volume[p] / V * cbar * 0.5 * d.uu;
      r.gradient[q] += material.modulus_derivative(density[q]) / material.young_modulus * cbar * (0.5 * d.uu - d.ul);
    }
    Vec3 up = Vec3::Zero();
    for (uint32_t e = band.point_offset[p]; e < band.point_offset[p + 1]; ++e)
      up += band.entry_weight[e] * u.segment<3>(Eigen::Index(3 * band.entry_node[e]));
    r.point_displacement[q] = up;
  }
  return r;
}

}  // namespace latmpm::optimize
