// The density sharpening of LETO without the narrow band, paper C Eq. (38) (Sec. 4.2.3):
// "a family of density mapping functions like Heaviside projection in SIMP, except that
// the functions are smoothly clamped at 0 and 1 to have zero gradient", with β raised from
// 1.01 to 10 during the optimisation. The equation is not legible in our copy; we take
//   s_β(ρ) = ρ^β / (ρ^β + (1 − ρ)^β),   ρ ∈ [0, 1],
// which has the stated properties: s(0) = 0, s(1) = 1, s(½) = ½, zero slope at 0 and 1 for
// every β > 1, the identity at β = 1 and a step at ½ as β grows (docs/paper-c.md).
#pragma once
#include <algorithm>
#include <cmath>

#include "mpm/real.hpp"

namespace latmpm::optimize {

using mpm::Real;

struct Sharpening {
  Real beta = 1;

  Real value(Real rho) const {
    const Real r = std::clamp(rho, Real(0), Real(1));
    const Real a = std::pow(r, beta), b = std::pow(1 - r, beta);
    return a / (a + b);
  }
  Real derivative(Real rho) const {
    const Real r = std::clamp(rho, Real(0), Real(1));
    if (r <= 0 || r >= 1) return beta > 1 ? 0 : 1;
    const Real a = std::pow(r, beta), b = std::pow(1 - r, beta);
    return beta * a * b / (r * (1 - r) * (a + b) * (a + b));
  }
};

}  // namespace latmpm::optimize
