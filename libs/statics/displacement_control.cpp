#include "statics/displacement_control.hpp"

#include <memory>

#include "core/errors.hpp"

namespace latmpm::statics {

namespace {
Dirichlet platen_conditions(const StaticProblem& problem, const PlatenLoading& loading, Real travel) {
  Dirichlet d(problem.dof_count());
  for (size_t n : loading.support_nodes) d.prescribe(n, Vec3::Zero());
  for (size_t n : loading.platen_nodes) d.prescribe(n, travel * loading.direction);
  return d;
}

// Σ over the nodes of the internal force along the platen's motion (N).
Real nodal_load(const std::vector<size_t>& nodes, const Vec3& direction, const Vector& f_int) {
  Real load = 0;
  for (size_t n : nodes) load += f_int.segment<3>(Eigen::Index(3 * n)).dot(direction);
  return load;
}

}  // namespace

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

  // Solves at `travel` from u; true when it converged (u, point updated), false otherwise.
  // With the predictor, Newton starts from the secant extrapolation of the last two
  // equilibria (its prescribed unknowns exact); where that inverts a point or does not
  // converge, from u itself, as without it.
  auto solve_at = [&](Real travel, Vector& state, PathPoint& point, std::string& failure) {
    const Dirichlet conditions = platen_conditions(problem, loading, travel);
    Vector trial = state;
    NewtonReport r;
    bool predicted = false;
    if (loading.predictor && u_before.size() == state.size() && stable_travel > travel_before) {
      trial += (travel - stable_travel) / (stable_travel - travel_before) * (state - u_before);
      for (size_t i = 0; i < conditions.fixed.size(); ++i)
        if (conditions.fixed[i]) trial[Eigen::Index(i)] = conditions.value[Eigen::Index(i)];
      predicted = problem.is_quadratic() || problem.min_jacobian(trial) > 0;
      if (predicted) r = solve_equilibrium(problem, conditions, trial, solver, newton);
    }
    point.predicted = predicted && r.converged;
    if (!point.predicted) {
      const int spent = r.iterations;  // from an abandoned prediction: counted too
      trial = state;
      r = solve_equilibrium(problem, conditions, trial, solver, newton);
      r.iterations += spent;
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
    point.newton_iterations = r.iterations;
    point.linear_iterations = r.linear_iterations;
    point.linear_residual = r.linear_residual;
    point.residual = r.residual.back();
    point.min_jacobian = r.min_jacobian;
    point.stable = true;
    if (loading.check_stability) {
      PhaseTimer timer(report.stability_check);
      problem.assemble_hessian(state, false);
      SparseMatrix& K = problem.hessian();
      constrain_rows_and_columns(K, conditions.fixed, mean_diagonal(K));
      point.stable = check_solver().factorize(K);
    }
    return true;
  };

  const Real step = loading.travel / loading.increments;
  for (int i = 1; i <= loading.increments; ++i) {
    PathPoint point;
    std::string failure;
    Vector next = u;
    const bool converged = solve_at(i * step, next, point, failure);
    // A load below the previous one: past a limit point (the peak of the static path).
    const bool past_peak = converged && loading.end_at_load_maximum && !report.points.empty() &&
                           point.load < report.points.back().load;
    if (past_peak) point.stable = false;
    if (converged && point.stable) {
      accept(next, point.travel);
      report.points.push_back(point);
      if (observe) observe(point, u);
      continue;
    }
    // Bracket the end of the static path between the last stable travel and this one.
    Real low = stable_travel, high = i * step;
    bool high_converged = converged;
    Real high_load = point.load;
    report.end_reason = past_peak ? "load maximum" : converged ? "tangent not positive definite" : failure;
    for (int b = 0; b < loading.bisections; ++b) {
      const Real mid = Real(0.5) * (low + high);
      PathPoint trial_point;
      std::string trial_failure;
      Vector trial = u;
      const bool trial_converged = solve_at(mid, trial, trial_point, trial_failure);
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
    if (converged) {  // the first unstable equilibrium closes the path
      report.points.push_back(point);
      if (observe) observe(point, next);
    }
    report.ended = true;
    report.end_travel = high;
    stable_travel = low;
    for (const PathPoint& p : report.points)
      if (p.stable && p.travel == stable_travel) report.last_stable_load = p.load;
    report.last_stable_travel = stable_travel;
    // Midpoint of the final bracket, the load interpolated where both ends converged.
    report.end_travel = Real(0.5) * (low + high);
    report.end_load = high_converged ? Real(0.5) * (report.last_stable_load + high_load) : report.last_stable_load;
    return report;
  }
  report.last_stable_travel = stable_travel;
  for (const PathPoint& p : report.points)
    if (p.stable && p.travel == stable_travel) report.last_stable_load = p.load;
  report.end_load = report.last_stable_load;
  return report;
}

}  // namespace latmpm::statics
