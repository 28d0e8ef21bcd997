#include "statics/projected_newton.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/errors.hpp"
#include "statics/inversion_free_step.hpp"

namespace latmpm::statics {

namespace {
Vector free_part(const Vector& v, const std::vector<char>& fixed) {
  Vector r = v;
  for (size_t i = 0; i < fixed.size(); ++i)
    if (fixed[i]) r[Eigen::Index(i)] = 0;
  return r;
}

// Prescribed minus current displacement on the prescribed unknowns, zero elsewhere.
Vector constrained_gap(const Dirichlet& dirichlet, const Vector& u) {
  Vector gap = Vector::Zero(u.size());
  for (size_t i = 0; i < dirichlet.fixed.size(); ++i)
    if (dirichlet.fixed[i]) gap[Eigen::Index(i)] = dirichlet.value[Eigen::Index(i)] - u[Eigen::Index(i)];
  return gap;
}

// Largest step along d keeping every det F_p ≥ margin·det F_p(u) (paper C Eq. 35).
Real step_bound(const StaticProblem& problem, const Vector& u, const Vector& d, Real margin) {
  const std::vector<Mat3> F = problem.deformation_gradients(u);
  std::vector<Mat3> D = problem.deformation_gradients(d);
  for (Mat3& m : D) m -= Mat3::Identity();
  return std::min(Real(1), inversion_free_step(F, D, margin));
}
}  // namespace

std::string linear_convergence_stall(const std::vector<Real>& residual, const std::vector<char>& projected_at_rest,
                                     const NewtonOptions& options) {
  assert(residual.size() == projected_at_rest.size() + 1);
  const int window = options.stall_window;
  const int steps = int(projected_at_rest.size());
  if (window <= 0 || steps < window) return {};
  for (int i = steps - window; i < steps; ++i) {
    const Real ratio = residual[size_t(i) + 1] / residual[size_t(i)];
    if (!projected_at_rest[size_t(i)] || !(ratio >= options.stall_ratio && ratio < 1)) return {};
  }
  // Every ratio < 1, so the window's fall is < 1 and its logarithm negative (no pow that could
  // round a rate near 1 to 1).
  const Real now = residual.back();
  const Real log_fall = std::log(now / residual[size_t(steps - window)]);
  const Real needed = std::ceil(Real(window) * std::log(options.tolerance / now) / log_fall);
  if (steps + needed <= options.max_iterations) return {};
  const Real rate = std::exp(log_fall / Real(window));
  char text[200];
  std::snprintf(text, sizeof text,
                "converging linearly (relative residual %.3g, x%.3g a step over %d projected steps): "
                "%.0f more steps to the tolerance, %d left",
                now, rate, window, needed, options.max_iterations - steps);
  return text;
}

std::string no_progress_stall(const std::vector<Real>& residual, size_t first_at_rest, const NewtonOptions& options) {
  assert(first_at_rest < residual.size());
  const size_t span = 2 * size_t(std::max(options.stall_window, 0));
  if (span == 0 || residual.size() <= first_at_rest + span) return {};
  const auto best = std::min_element(residual.begin() + std::ptrdiff_t(first_at_rest), residual.end());
  const size_t since = size_t(residual.end() - best) - 1;  // steps taken since the best residual
  if (since < span) return {};
  char text[200];
  std::snprintf(text, sizeof text,
                "no progress: the relative residual has stayed above its best, %.3g, for %zu steps (now %.3g)",
                *best, since, residual.back());
  return text;
}

NewtonReport solve_equilibrium(StaticProblem& problem, const Dirichlet& dirichlet, Vector& u,
                               SparseSolver& solver, const NewtonOptions& options) {
  NewtonReport report;
  const std::vector<char>& fixed = dirichlet.fixed;
  const Vector& f_ext = problem.external_force();
  // The residual at which the true tangent was last found indefinite (or not descending):
  // tried again once the residual has fallen by retry_true_tangent_after since then (the
  // struts' bending may leave it indefinite far from the solution, not near it).
  Real true_tangent_failed_at = std::numeric_limits<Real>::infinity();
  // Per step taken: true when it was a projected step with the platen at rest (the kind of
  // step whose steady linear convergence the stall rule looks for).
  std::vector<char> projected_at_rest;
  bool true_tangent_retried_on_stall = false;
  int first_at_rest = -1;  // index of the first residual with the prescribed unknowns in place
  for (int k = 0;; ++k) {
    const Vector f_int = problem.internal_force(u);
    const Vector g = f_int - f_ext;
    const Vector constraint_gap = constrained_gap(dirichlet, u);
    const Real scale = std::max({f_int.norm(), f_ext.norm(), std::numeric_limits<Real>::min()});
    const Real residual = free_part(g, fixed).norm() / scale;
    const Real energy = problem.energy(u);
    report.residual.push_back(residual);
    report.energy.push_back(energy);
    const bool boundary_moves = constraint_gap.lpNorm<Eigen::Infinity>() > 0;
    if (!boundary_moves && residual <= options.tolerance) {
      report.converged = true;
      break;
    }
    if (options.stop_requested && options.stop_requested()) {
      report.stopped = true;
      report.failure = "stopped before Newton step " + std::to_string(k + 1);
      break;
    }
    if (k == options.max_iterations) {
      report.failure = "no convergence in " + std::to_string(k) + " Newton steps (relative residual " +
                       std::to_string(residual) + ")";
      break;
    }
    if (first_at_rest < 0 && !boundary_moves) first_at_rest = k;
    std::string stall = linear_convergence_stall(report.residual, projected_at_rest, options);
    if (!stall.empty() && !std::isinf(true_tangent_failed_at) && !true_tangent_retried_on_stall) {
      // Before failing, one more try of the true tangent, which is skipped until the residual
      // has fallen tenfold since it was found indefinite: near a stable equilibrium it is
      // positive definite again and converges where the projected steps creep (paper-size
      // T2P30 at 10.1 mm: projected steps stuck at 1.4e-5, 0.1 of where the true tangent had
      // failed being 1.2e-5). The window then starts again.
      true_tangent_retried_on_stall = true;
      true_tangent_failed_at = std::numeric_limits<Real>::infinity();
      projected_at_rest.assign(projected_at_rest.size(), 0);
      stall.clear();
    }
    if (stall.empty() && first_at_rest >= 0)
      stall = no_progress_stall(report.residual, size_t(first_at_rest), options);
    if (!stall.empty()) {
      report.failure = stall;
      break;
    }

    // Newton direction (step 2–3): the true Hessian where it is positive definite
    // (quadratic convergence), otherwise the projected one.
    const bool try_true = !boundary_moves && residual <= options.true_tangent_below &&
                          (std::isinf(true_tangent_failed_at) ||
                           residual <= options.retry_true_tangent_after * true_tangent_failed_at);
    // An iterative solver builds its preconditioner for an indefinite true tangent too: its
    // direction is then taken only when it solved and descends, else the projected one.
    bool factorized = false, krylov_solved = false;
    const int true_steps_before = report.true_tangent_steps;
    Vector rhs, d;
    LinearSolveStats stats;
    for (const bool projected : {false, true}) {
      if (!projected && !try_true) continue;
      problem.assemble_hessian(u, projected);
      SparseMatrix& H = problem.hessian();
      // Free rows: −g − H_fc·gap. Prescribed rows decouple once constrained (scaled
      // identity, columns zeroed) and take their gap after the solve, so their right-hand
      // side is 0: an iterative solver's relative tolerance then measures the free rows only.
      rhs = -g - H * constraint_gap;
      const Real diagonal = mean_diagonal(H);
      for (size_t i = 0; i < fixed.size(); ++i)
        if (fixed[i]) rhs[Eigen::Index(i)] = 0;
      constrain_rows_and_columns(H, fixed, diagonal);
      // The shift fixes the zero-energy modes of the point quadrature (docs/statics.md):
      // negligible, and raised only while a projected factorisation fails.
      Real shift = options.shift;
      for (Eigen::Index i = 0; i < H.rows(); ++i) H.coeffRef(i, i) += shift * diagonal;
      // A Krylov step: CG preconditioned by the factor the solver holds. A true-tangent
      // direction is kept only where it descends; a direction of non-positive curvature
      // proves the true tangent indefinite, as a failed factorisation does.
      if (options.krylov_iterations > 0 && solver.has_factor()) {
        const Real forcing =
            boundary_moves ? options.krylov_forcing
                           : std::clamp(Real(0.1) * residual, Real(1e-12), options.krylov_forcing);
        Vector dk;
        const KrylovResult kr = solver.solve_preconditioned(H, rhs, forcing, options.krylov_iterations, dk);
        stats.iterations = kr.iterations;
        stats.relative_residual = kr.relative_residual;
        if (kr.outcome == KrylovOutcome::solved && (projected || g.dot(free_part(dk, fixed)) < 0)) {
          d = std::move(dk);
          if (!projected) ++report.true_tangent_steps;
          ++report.krylov_steps;
          report.last_step_true_tangent = false;  // not factorised: says nothing of definiteness
          krylov_solved = true;
          break;
        }
        report.linear_iterations += kr.iterations;  // spent before the factorisation
        // Non-positive curvature, or a solution at forcing ≤ 1e-2 that does not descend: the
        // true tangent is indefinite (a positive definite one gives a descent direction), so
        // on to the projected Hessian without factorising it.
        if (!projected && kr.outcome != KrylovOutcome::not_converged) {
          true_tangent_failed_at = residual;
          continue;
        }
      }
      for (;;) {
        factorized = solver.factorize(H);
        if (factorized || !projected || shift * 1e3 > 1e-2) break;
        shift *= 1e3;
        for (Eigen::Index i = 0; i < H.rows(); ++i) H.coeffRef(i, i) += shift * diagonal;
      }
      if (factorized && !projected) {
        try {
          d = solver.solve(rhs, stats);
          factorized = g.dot(free_part(d, fixed)) < 0;
        } catch (const NumericalError&) {
          factorized = false;
        }
      } else if (factorized) {
        d = solver.solve(rhs, stats);
      }
      if (factorized) {
        if (!projected) ++report.true_tangent_steps;
        report.last_step_true_tangent = !projected;
        break;
      }
      if (!projected) true_tangent_failed_at = residual;
    }
    if (!factorized && !krylov_solved) {
      report.failure = "the projected Hessian is singular (a part of the body is not held)";
      break;
    }
    for (size_t i = 0; i < fixed.size(); ++i)  // exactly, whatever the solver's tolerance
      if (fixed[i]) d[Eigen::Index(i)] = constraint_gap[Eigen::Index(i)];
    report.linear_iterations += stats.iterations;
    report.linear_residual = stats.relative_residual;
    ++report.iterations;

    // Step length (step 4): inversion-free bound, then det F > 0 before any energy.
    Real alpha = problem.is_quadratic() ? Real(1) : step_bound(problem, u, d, options.inversion_margin);
    const Real slope = g.dot(d);
    const Real allowance = 1e-12 * std::abs(energy);  // round-off of E near the minimum
    int halvings = 0;
    for (;; alpha *= Real(0.5), ++halvings) {
      if (halvings > options.max_halvings) break;
      const Vector trial = u + alpha * d;
      if (!problem.is_quadratic() && problem.min_jacobian(trial) <= 0) continue;
      if (boundary_moves) break;  // the prescribed motion raises E: no sufficient decrease to ask
      if (problem.energy(trial) <= energy + options.armijo * alpha * slope + allowance) break;
    }
    if (halvings > options.max_halvings) {
      report.failure = "the line search found no decrease of the energy";
      break;
    }
    u += alpha * d;
    report.step.push_back(alpha);
    projected_at_rest.push_back(!boundary_moves && report.true_tangent_steps == true_steps_before);
    if (options.on_step) {
      NewtonStep s;
      s.iteration = report.iterations;
      s.residual_before = residual;
      s.alpha = alpha;
      s.true_tangent = report.true_tangent_steps > true_steps_before;
      s.krylov = krylov_solved;
      s.linear_iterations = stats.iterations;
      options.on_step(s);
    }
  }
  report.min_jacobian = problem.min_jacobian(u);
  if (!report.converged && !report.stopped && options.on_failure) options.on_failure(report.failure);
  return report;
}

}  // namespace latmpm::statics
