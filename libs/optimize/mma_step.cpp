#include "optimize/mma_step.hpp"

#include <nlopt.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/errors.hpp"

namespace latmpm::optimize {
namespace {

struct Session {
  const MmaInput* in = nullptr;
  Real objective_scale = 1, constraint_scale = 1;
  int evaluations = 0;
  std::vector<Real> proposed;
  nlopt_opt opt = nullptr;
};

double objective(unsigned n, const double* x, double* grad, void* data) {
  auto& s = *static_cast<Session*>(data);
  if (++s.evaluations == 1) {  // the current design: the caller's values
    for (unsigned j = 0; j < n; ++j) grad[j] = s.objective_scale * s.in->objective_gradient[j];
    return s.objective_scale * s.in->objective;
  }
  s.proposed.assign(x, x + n);  // MMA's next point: stop before evaluating it
  nlopt_force_stop(s.opt);
  if (grad) std::fill(grad, grad + n, 0.0);
  return 0;
}

double constraint(unsigned n, const double* /*x*/, double* grad, void* data) {
  auto& s = *static_cast<Session*>(data);
  for (unsigned j = 0; j < n; ++j) grad[j] = s.constraint_scale * s.in->constraint_gradient[j];
  return s.constraint_scale * s.in->constraint;
}

Real norm(const std::vector<Real>& v) {
  Real sum = 0;
  for (Real a : v) sum += a * a;
  return std::sqrt(sum);
}

}  // namespace

std::vector<Real> mma_step(const MmaInput& in) {
  const unsigned n = unsigned(in.x.size());
  Session s;
  s.in = &in;
  std::vector<double> lo(n), hi(n), x(in.x.begin(), in.x.end());
  for (unsigned j = 0; j < n; ++j) {
    lo[j] = std::max(in.lower[j], in.x[j] - in.move[j]);
    hi[j] = std::min(in.upper[j], in.x[j] + in.move[j]);
    x[j] = std::clamp(x[j], lo[j], hi[j]);
  }
  // Paper C Sec. 4.1 (2): objective and constraint gradients scaled to unit 2-norm. Then
  // both by one more common factor: NLopt's MMA (the CCSA form) adds ρ/2 dx²/(σ² − dx²) per
  // variable with ρ = 1 at its first iteration, which each step here is; scaled so that the
  // largest |∂f/∂x_j| σ_j is 1e3, that term is negligible and the step is MMA's convex
  // approximation with asymptotes x ± σ, σ = half the move-limited box (mma_step.hpp).
  const Real gf = norm(in.objective_gradient), gg = norm(in.constraint_gradient);
  s.objective_scale = gf > 0 ? 1 / gf : 1;
  s.constraint_scale = gg > 0 ? 1 / gg : 1;
  Real reach_f = 0, reach_g = 0;
  for (unsigned j = 0; j < n; ++j) {
    const Real sigma = 0.5 * (hi[j] - lo[j]);
    reach_f = std::max(reach_f, std::abs(in.objective_gradient[j]) * s.objective_scale * sigma);
    reach_g = std::max(reach_g, std::abs(in.constraint_gradient[j]) * s.constraint_scale * sigma);
  }
  const Real reach = std::min(reach_f > 0 ? reach_f : 1, reach_g > 0 ? reach_g : 1);
  s.objective_scale *= 1e3 / reach;
  s.constraint_scale *= 1e3 / reach;
  s.opt = nlopt_create(NLOPT_LD_MMA, n);
  if (!s.opt) throw NumericalError("mma: NLopt could not create an MMA optimiser");
  nlopt_set_lower_bounds(s.opt, lo.data());
  nlopt_set_upper_bounds(s.opt, hi.data());
  nlopt_set_min_objective(s.opt, objective, &s);
  nlopt_add_inequality_constraint(s.opt, constraint, &s, 0.0);
  double value = 0;
  const nlopt_result result = nlopt_optimize(s.opt, x.data(), &value);
  nlopt_destroy(s.opt);
  if (s.proposed.size() != n)
    throw NumericalError("mma: NLopt stopped without a new design (nlopt result " + std::to_string(int(result)) + ")");
  return std::vector<Real>(s.proposed.begin(), s.proposed.end());
}

}  // namespace latmpm::optimize
