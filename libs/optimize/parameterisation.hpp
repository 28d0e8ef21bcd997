// How design variables x define the densities ρ_q of the quadrature points: LETO's carrier
// particles (leto_design.hpp) or SIMP's cell densities with filter and projection
// (simp_design.hpp). The optimisation loop (optimisation.hpp) sees only this interface.
#pragma once
#include <string>
#include <vector>

#include "mpm/real.hpp"

namespace latmpm::optimize {

using mpm::Real;

class Parameterisation {
 public:
  virtual ~Parameterisation() = default;
  virtual std::string name() const = 0;
  virtual std::vector<Real> initial() const = 0;
  // Global bounds and the largest change per iteration, per variable.
  virtual void bounds(std::vector<Real>& lower, std::vector<Real>& upper, std::vector<Real>& move) const = 0;
  // Continuation at the start of iteration k (SIMP's projection sharpness).
  virtual void start_iteration(int /*k*/) {}
  // Whether the continuation has reached its end (convergence is tested only then).
  virtual bool continuation_done() const { return true; }
  // ρ_q of x; keeps what pull_back needs.
  virtual void densities(const std::vector<Real>& x, std::vector<Real>& density) = 0;
  // ∂J/∂x from ∂J/∂ρ_q, at the x of the last densities() call.
  virtual std::vector<Real> pull_back(const std::vector<Real>& x, const std::vector<Real>& d_density) const = 0;
};

}  // namespace latmpm::optimize
