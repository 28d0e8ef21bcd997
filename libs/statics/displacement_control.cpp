#include "statics/displacement_control.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <tuple>
#include <utility>

#include "core/errors.hpp"

namespace latmpm::statics {

namespace {
Dirichlet platen_conditions(const StaticProblem& problem, const PlatenLoading& loading, Real travel) {
  Dirichlet d(problem.dof_count());
  for (size_t n : loading.support_nodes) d.prescribe(n, Vec3::Zero());
  for (size_t n : loading.platen_nodes) d.prescribe(n, travel * loading.direction);
  return d;
}

// Below this relative residual a positive definite true tangent of Newton's last step
// answers the stability check (displacement_control.hpp).
constexpr Real newton_check_residual = 1e-4;

// Σ over the nodes of the internal force along the platen's motion (N).
Real nodal_load(const std::vector<size_t>& nodes, const Vec3& direction, const Vector& f_int) {
  Real load = 0;
  for (size_t n : nodes) load += f_int.segment<3>(Eigen::Index(3 * n)).dot(direction);
  return load;
}

}  // namespace

std::pair<Real, Real> parabola_vertex(Real t0, Real f0, Real t1, Real f1, Real t2, Real f2) {
  const Real d01 = (f1 - f0) / (t1 - t0), d12 = (f2 - f1) / (t2 - t1);
  const Real a = (d12 - d01) / (t2 - t0);  // F = f1 + d01 (t − t1) + a (t − t0)(t − t1)
  const Real slope1 = d01 + a * (t1 - t0);  // F'(t1)
  const Real t = t1 - slope1 / (2 * a);
  return {t, f1 + d01 * (t - t1) + a * (t - t0) * (t - t1)};
}

PathReport load_by_platen(StaticProblem& problem, const PlatenLoading& loading, SparseSolver& solver,
                          const NewtonOptions& newton, const IncrementObserver& observe) {
  if (loading.increments < 1) throw InputError("static solver", "increments", "must be at least 1");
  PathReport report;
  // The stability check needs a direct solver (CG and AMG cannot tell an indefinite
  // matrix): the Newton solver where it is one, else a CHOLMOD of its own, made on first use.
  std::unique_ptr<SparseSolver> own_check;
  auto check_solver = [&]() -> SparseSolver& {
    if (solver.is_direct()) return solver;
    if (!own_check) own_check = std::make_unique<SparseSolver>(LinearSolverKind::cholmod);
    return *own_check;
  };
  // The last stable equilibrium u at stable_travel, and the one before it (the predictor's
  // second point).
  Vector u = Vector::Zero(Eigen::Index(problem.dof_count()));
  Real stable_travel = 0;
  Vector u_before;
  Real travel_before = 0;
  auto accept = [&](const Vector& state, Real travel) {
    u_before.swap(u);
    travel_before = stable_travel;
    u = state;
    stable_travel = travel;
  };

  // A stop request (a signal: core/interruption.hpp) ends the path where it stands: no retry,
  // no bisection; the converged increments are the answer so far.
  bool stopped = false;
  // Solves at `travel` from u; true when it converged (u, point updated), false otherwise
  // (`stopped` set where a stop request ended a solve). With the predictor, Newton starts from
  // the secant extrapolation of the last two equilibria (its prescribed unknowns exact); where
  // that inverts a point or does not converge, from u itself, as without it. `retry` false:
  // a step that will be halved if it fails gets the first attempt only (on the paper-size T2
  // paths each attempt that fails costs 20 steps of ~25 s; the halved step is the better retry).
  auto solve_at = [&](Real travel, Vector& state, PathPoint& point, std::string& failure, bool retry) {
    const Dirichlet conditions = platen_conditions(problem, loading, travel);
    Vector trial = state;
    NewtonReport r;
    // What abandoned attempts spent, counted in the point's figures.
    int spent_iterations = 0, spent_true_tangent = 0, spent_linear = 0, spent_krylov = 0;
    auto abandon = [&] {
      spent_iterations += r.iterations, spent_true_tangent += r.true_tangent_steps;
      spent_linear += r.linear_iterations, spent_krylov += r.krylov_steps;
    };
    // One Newton solve from `trial`; false where a stop request ended it (then `stopped`).
    auto solve = [&](const NewtonOptions& options) {
      r = solve_equilibrium(problem, conditions, trial, solver, options);
      stopped = r.stopped;
      return !stopped;
    };
    bool predicted = false;
    if (loading.predictor && u_before.size() == state.size() && stable_travel > travel_before) {
      trial += (travel - stable_travel) / (stable_travel - travel_before) * (state - u_before);
      for (size_t i = 0; i < conditions.fixed.size(); ++i)
        if (conditions.fixed[i]) trial[Eigen::Index(i)] = conditions.value[Eigen::Index(i)];
      predicted = problem.is_quadratic() || problem.min_jacobian(trial) > 0;
      if (predicted && !solve(newton)) return false;
    }
    point.predicted = predicted && r.converged;
    // A failed prediction is solved again from u only where the step will not be halved instead.
    if (!point.predicted && (retry || !predicted)) {
      abandon();  // an abandoned prediction (or none: zeros)
      trial = state;
      if (!solve(newton)) return false;
    }
    if (!r.converged && retry && r.krylov_steps + spent_krylov > 0) {
      // Krylov steps take other (inexact) directions: where a solve that took any fails, the
      // increment is solved again by factorising Newton, so that they never end a path it
      // would continue. A solve that took none already was factorising Newton.
      abandon();
      NewtonOptions factorising = newton;
      factorising.krylov_iterations = 0;
      trial = state;
      point.predicted = false;
      if (!solve(factorising)) return false;
    }
    if (!r.converged) {
      failure = r.failure;
      return false;
    }
    state = trial;
    point.travel = travel;
    const Vector f_int = problem.internal_force(state);
    point.load = nodal_load(loading.platen_nodes, loading.direction, f_int);
    point.support_load = -nodal_load(loading.support_nodes, loading.direction, f_int);
    point.energy = r.energy.back() + problem.external_force().dot(state);
    point.newton_iterations = r.iterations + spent_iterations;
    point.true_tangent_steps = r.true_tangent_steps + spent_true_tangent;
    point.linear_iterations = r.linear_iterations + spent_linear;
    point.krylov_steps = r.krylov_steps + spent_krylov;
    point.linear_residual = r.linear_residual;
    point.residual = r.residual.back();
    point.min_jacobian = r.min_jacobian;
    point.stable = true;
    const bool newton_answers = solver.is_direct() && r.last_step_true_tangent && r.residual.size() >= 2 &&
                                r.residual[r.residual.size() - 2] <= newton_check_residual;
    if (loading.check_stability && newton_answers) {
      ++report.checks_from_newton;
    } else if (loading.check_stability) {
      PhaseTimer timer(report.stability_check);
      problem.assemble_hessian(state, false);
      SparseMatrix& K = problem.hessian();
      constrain_rows_and_columns(K, conditions.fixed, mean_diagonal(K));
      point.stable = check_solver().factorize(K);
    }
    return true;
  };

  // The report's last stable travel and its load (0 at the start).
  auto record_last_stable = [&] {
    report.last_stable_travel = stable_travel;
    report.last_stable_load = 0;
    for (const PathPoint& p : report.points)
      if (p.stable && p.travel == stable_travel) report.last_stable_load = p.load;
  };

  auto end_stopped = [&] {
    report.ended = true;
    report.stopped = true;
    report.end_reason = "stopped";
    record_last_stable();
    report.end_travel = stable_travel;
    report.end_load = report.last_stable_load;
    return report;
  };

  const Real base_step = loading.travel / loading.increments;
  const Real max_step = base_step * std::max(Real(1), loading.max_step_growth);
  // A Newton failure says only that this step was too long for Newton from the last
  // equilibrium, not that no equilibrium lies beyond it: the step is halved and tried again
  // from there, and only a failure at the smallest step (the increment over 2^bisections)
  // ends the path. (Until 2026-11-26 the failing travel stayed the bracket's upper end while
  // its lower end was bisected towards it; on the paper-size T1P20 and T1P30 every bisection
  // converged, so the reported end was only where one long step had failed.)
  const Real min_step = std::ldexp(base_step, -loading.bisections);
  const Real end_tolerance = 1e-9 * loading.travel;
  // In increments: below a quarter of the smallest step, above rounding.
  const Real grid_tolerance = std::max(Real(1e-9), Real(0.25) * min_step / base_step);
  Real step = base_step;
  while (stable_travel < loading.travel - end_tolerance) {
    if (newton.stop_requested && newton.stop_requested()) return end_stopped();
    Real target = loading.travel;
    if (loading.travel - stable_travel >= step + end_tolerance) {
      target = stable_travel + step;
      if (max_step <= base_step) {
        // Fixed increments: the travels k × base_step, a cut step never passing the next one.
        const Real next_grid = (std::floor(stable_travel / base_step + grid_tolerance) + 1) * base_step;
        if (target > next_grid - end_tolerance) target = next_grid;
      }
    }
    PathPoint point;
    std::string failure;
    Vector next = u;
    const bool can_cut_back = target - stable_travel > min_step * (1 + 1e-9);
    const bool converged = solve_at(target, next, point, failure, !can_cut_back);
    if (stopped) return end_stopped();
    if (!converged && can_cut_back) {  // too long a step: halve the one taken (it may have
      step = Real(0.5) * (target - stable_travel);  // been clipped to a grid travel), retry
      ++report.cut_backs;
      continue;
    }
    // A load below the previous one: past a limit point (the peak of the static path).
    const bool past_peak = converged && loading.end_at_load_maximum && !report.points.empty() &&
                           point.load < report.points.back().load;
    if (past_peak) point.stable = false;
    if (converged && point.stable) {
      accept(next, point.travel);
      report.points.push_back(point);
      if (observe) observe(point, u);
      // Grow while Newton is fast, shrink back where it slows (near a peak the load-maximum
      // test needs close points).
      if (point.newton_iterations <= loading.fast_newton)
        step = std::min(max_step, step * loading.step_growth);
      else if (point.newton_iterations > 2 * loading.fast_newton)
        step = std::max(std::min(step, base_step), step / loading.step_growth);
      continue;
    }
    if (!converged) {  // a Newton failure at the smallest step: the end's bracket is that step
      report.ended = true;
      report.end_reason = failure;
      record_last_stable();
      report.end_travel = Real(0.5) * (stable_travel + target);
      report.end_load = report.last_stable_load;
      return report;
    }
    report.ended = true;
    report.end_reason = past_peak ? "load maximum" : "tangent not positive definite";
    if (past_peak) {
      // The peak lies between the last two stable loads' travel and this one: the vertex of
      // the parabola through the last three points (the start counts as (0, 0)). Bisection
      // finds no better: on a flat top every bisection load may fall (docs/statics.md).
      const size_t n = report.points.size();
      const Real t0 = n >= 2 ? report.points[n - 2].travel : 0, f0 = n >= 2 ? report.points[n - 2].load : 0;
      const PathPoint& top = report.points.back();
      std::tie(report.end_travel, report.end_load) =
          parabola_vertex(t0, f0, top.travel, top.load, point.travel, point.load);
      report.last_stable_travel = top.travel;
      report.last_stable_load = top.load;
      report.points.push_back(point);
      if (observe) observe(point, next);
      return report;
    }
    // An indefinite tangent: bracket the travel where it turns between the last stable travel
    // and this one (a bisection travel that does not converge counts as past it).
    Real low = stable_travel, high = target;
    bool high_converged = true;
    Real high_load = point.load;
    for (int b = 0; b < loading.bisections; ++b) {
      const Real mid = Real(0.5) * (low + high);
      PathPoint trial_point;
      std::string trial_failure;
      Vector trial = u;
      const bool trial_converged = solve_at(mid, trial, trial_point, trial_failure, true);
      if (stopped) return end_stopped();
      if (trial_converged && loading.end_at_load_maximum && !report.points.empty() &&
          trial_point.load < report.points.back().load)
        trial_point.stable = false;
      if (trial_converged && trial_point.stable) {
        accept(trial, mid);
        low = mid;
        report.points.push_back(trial_point);
        if (observe) observe(trial_point, u);
      } else {
        high = mid;
        high_converged = trial_converged;
        high_load = trial_point.load;
      }
    }
    report.points.push_back(point);  // the first unstable equilibrium closes the path
    if (observe) observe(point, next);
    stable_travel = low;
    record_last_stable();
    // Midpoint of the final bracket, the load interpolated where both ends converged.
    report.end_travel = Real(0.5) * (low + high);
    report.end_load = high_converged ? Real(0.5) * (report.last_stable_load + high_load) : report.last_stable_load;
    return report;
  }
  record_last_stable();
  report.end_load = report.last_stable_load;
  return report;
}

}  // namespace latmpm::statics
