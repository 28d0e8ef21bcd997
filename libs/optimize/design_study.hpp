// One method (LETO or the SIMP baseline) run on a scene and evaluated as paper C Sec. 4.2
// does: the final design binarised (LETO at ρ > 0.9 after the connectivity correction of
// Sec. 3.4, SIMP at ρ̄ > 0.5), its volume fraction, and its compliance at the optimisation
// resolution and on a grid refined `refine` times, where each quadrature point of the design
// becomes one refined cell (void cells as a weak material, E_min = 1e-9 E, as in SIMP).
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "optimize/optimize_scene.hpp"

namespace latmpm::optimize {

struct MethodOutcome {
  std::string method;
  OptimisationResult result;
  std::vector<Real> binary;          // 0/1 per quadrature point of the final design
  Real volume_fraction = 0;          // of `binary`
  Real compliance_last = 0;          // C of the last iteration (grey for SIMP), J
  Real compliance_binary = 0;        // the binary design at the optimisation resolution, J
  Real compliance_refined = 0;       // the binary design on the refined grid, J (0: not evaluated)
  Real compliance_other_model = 0;   // under the other material model, optimisation grid, J (0: not evaluated)
  size_t corrections = 0;            // paths the connectivity correction created
  size_t components = 0;             // connected components of the binary design (quadrature graph)
  Real seconds_per_iteration = 0;    // mean wall time of an iteration
};

// Compliance of a 0/1 design on `grid` refined `refine` times (1: the grid itself).
Real evaluate_binary_design(const DesignGrid& grid, const std::vector<Real>& binary, const LoadCase& load_case,
                            const SimpMaterial& material, int refine);

MethodOutcome run_method(const OptimizeScene& scene, const std::string& method,
                         const std::function<void(const IterationRecord&)>& on_iteration = {});

}  // namespace latmpm::optimize
