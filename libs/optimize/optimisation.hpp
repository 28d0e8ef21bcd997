// The optimisation loop of paper C Sec. 2.2 (steps 1-4), for any parameterisation:
//   1. ρ_q from the design variables (C2P for LETO; filter + projection for SIMP);
//   2. narrow band (Sec. 3.4, Eq. 36): the largest connected component of {ρ_q > t_k},
//      with the threshold t_k rising linearly from `start` to `end` over `ramp_iterations`
//      (Fig. 6), treated as constant within an iteration (the paper's alternating scheme);
//      lowered for an iteration where it would cut the loads from the supports; an
//      iteration whose band no threshold makes solvable uses the weak material instead;
//      or, without the band, every point with a weak material (E_min = 1e-9 E);
//   3. static solve, compliance C and ∂C/∂ρ_q (compliance.hpp), volume fraction
//      v = Σ m_q ρ_q V_q / V_domain (Eq. 15-16, m_q the band mask);
//   4. one MMA step (mma_step.hpp) on min C s.t. v − v* ≤ 0.
// The points carrying a load are solid and not designed (ρ = 1, no sensitivity): the load
// stays on the structure (paper C loads a grid node; docs/paper-c.md).
// The result is the last design until the band (and SIMP's β) reach their end, then the
// stiffest design that meets the volume bound within 0.5 %.
// Stops when C changed by less than `tolerance` (relative) over 5 iterations, the volume
// bound holds within 0.5 %, the band threshold (and SIMP's continuation) are at their end;
// or after max_iterations.
#pragma once
#include <functional>
#include <vector>

#include "optimize/compliance.hpp"
#include "optimize/parameterisation.hpp"

namespace latmpm::optimize {

struct NarrowBandSchedule {
  bool enabled = true;
  Real start = 0.01, end = 0.9;  // thresholds t_0 and t_final
  int ramp_iterations = 90;
  Real threshold(int k) const;
};

struct OptimisationSettings {
  Real volume_fraction = 0.3;  // v*, in (0, 1)
  int max_iterations = 200;
  Real tolerance = 1e-3;
  SimpMaterial material;       // weak_ratio is set by the band choice
  NarrowBandSchedule band;
};

struct IterationRecord {
  int iteration = 0;
  Real compliance = 0, volume_fraction = 0, threshold = 0, seconds = 0;
  size_t active_points = 0, unknowns = 0;
  int newton_iterations = 0;  // of the static solve (1 for linear elasticity)
  int load_steps = 0;         // neo-Hookean: load steps from rest (0: the whole load from the last equilibrium)
};

struct OptimisationResult {
  std::vector<Real> density;  // ρ_q of the kept design (0 outside the band)
  std::vector<char> active;   // the final band mask
  std::vector<Real> x;        // the final design variables
  std::vector<IterationRecord> history;
  bool converged = false;
  // Neo-Hookean: iterations whose nonlinear equilibrium failed (a band with a mechanism,
  // e.g. a cell holding one point) and that stepped on the linear compliance instead.
  int linear_fallbacks = 0;
};

OptimisationResult optimise(const DesignGrid& grid, const LoadCase& load_case, Parameterisation& design,
                            const OptimisationSettings& settings,
                            const std::function<void(const IterationRecord&)>& on_iteration = {});

// Volume fraction Σ ρ_q V_q / V_domain of quadrature densities.
Real volume_fraction(const DesignGrid& grid, const std::vector<Real>& density);

}  // namespace latmpm::optimize
