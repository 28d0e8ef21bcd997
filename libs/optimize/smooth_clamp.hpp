// The smooth clamping of a quadrature point's kernel sum to at most one, paper C Eq. (11)-(12)
// (Fig. 4): the identity below `knee`, one above 2 − knee, and between them the quadratic
//   c(x) = x − (x − a)² / (2 (b − a)),  a = knee, b = 2 − knee,
// whose value and slope join both sides (c(b) = 1, c'(a) = 1, c'(b) = 0). The paper's
// equation is not legible in our copy; this C¹ form has the properties it states: linear up
// to the knee, exactly one with zero derivative above its end, so gathering carriers cannot
// make material stiffer than the solid (docs/paper-c.md).
#pragma once
#include "mpm/real.hpp"

namespace latmpm::optimize {

using mpm::Real;

struct SmoothClamp {
  Real knee = 0.9;  // a in (0, 1)

  Real value(Real x) const {
    const Real a = knee, b = 2 - knee;
    if (x <= a) return x;
    if (x >= b) return 1;
    return x - (x - a) * (x - a) / (2 * (b - a));
  }
  Real derivative(Real x) const {
    const Real a = knee, b = 2 - knee;
    if (x <= a) return 1;
    if (x >= b) return 0;
    return 1 - (x - a) / (b - a);
  }
};

}  // namespace latmpm::optimize
