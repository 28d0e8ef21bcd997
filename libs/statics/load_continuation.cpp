#include "statics/load_continuation.hpp"

#include <algorithm>

namespace latmpm::statics {

namespace {

void set_load(StaticProblem& problem, const std::vector<Vec3>& force, Real factor) {
  std::vector<Vec3> scaled = force;
  for (Vec3& f : scaled) f *= factor;
  problem.set_point_forces(scaled);
}

}  // namespace

ContinuationReport solve_by_load_continuation(StaticProblem& problem, const Dirichlet& dirichlet,
                                              const std::vector<Vec3>& force, Vector& u, SparseSolver& solver,
                                              const LoadContinuation& settings) {
  ContinuationReport report;
  auto solved = [&](const NewtonReport& r) {
    return r.converged || (r.iterations > 0 && r.residual.back() <= settings.accepted);
  };
  // A Newton solve from `v` under λ f: v is its result (kept only when it converged).
  auto attempt = [&](Vector& v, Real factor) {
    set_load(problem, force, factor);
    Vector trial = v;
    report.last = solve_equilibrium(problem, dirichlet, trial, solver, settings.newton);
    report.newton_iterations += report.last.iterations;
    if (!solved(report.last)) return false;
    v = trial;
    return true;
  };

  if (settings.try_start_first && u.size() == Eigen::Index(problem.dof_count()) && u.any() &&
      problem.min_jacobian(u) > 0 && attempt(u, 1)) {
    report.converged = report.from_start = true;
    report.load_factor = 1;
    return report;
  }

  u = Vector::Zero(Eigen::Index(problem.dof_count()));
  const Real smallest = Real(1) / Real(std::max(1, settings.max_increments));
  Real lambda = 0, step = std::clamp(settings.first_step, smallest, Real(1));
  while (lambda < 1) {
    step = std::min(step, 1 - lambda);
    const bool last = lambda + step >= 1 - 1e-12;
    if (attempt(u, last ? Real(1) : lambda + step)) {
      lambda = last ? Real(1) : lambda + step;
      ++report.steps;
      step *= 2;
      continue;
    }
    ++report.failed_steps;
    if (step <= smallest * (1 + 1e-9)) {
      report.failure = "load step " + std::to_string(step) + " from load factor " + std::to_string(lambda) +
                       " failed: " + report.last.failure;
      break;
    }
    step = std::max(smallest, step / 2);
  }
  report.load_factor = lambda;
  report.converged = lambda >= 1;
  set_load(problem, force, 1);
  return report;
}

}  // namespace latmpm::statics
