// The SPH cubic spline kernel of the carrier-to-quadrature transfer, paper C Eq. (8), in
// its compact-support form (support radius H, q = r/H):
//   W(r, H) = σ_d / H^d · { 6(q³ − q²) + 1      0 ≤ q ≤ ½
//                          { 2(1 − q)³           ½ < q ≤ 1
//                          { 0                   q > 1
// with σ_2 = 40/(7π) and σ_3 = 8/π, so that ∫ W dV = 1 (the partition of unity Sec. 3.1
// relies on for the initial volume).
#pragma once
#include <cmath>

#include "mpm/real.hpp"

namespace latmpm::optimize {

using mpm::Real;

struct CubicSplineKernel {
  Real radius = 0;  // H, m
  int dimension = 3;

  Real normalisation() const {
    const Real pi = 3.14159265358979323846;
    const Real sigma = dimension == 2 ? 40 / (7 * pi) : 8 / pi;
    return sigma / std::pow(radius, dimension);
  }
  // W(r), 1/m^d.
  Real value(Real r) const {
    const Real q = r / radius;
    if (q >= 1) return 0;
    const Real w = q <= 0.5 ? 6 * (q * q * q - q * q) + 1 : 2 * (1 - q) * (1 - q) * (1 - q);
    return normalisation() * w;
  }
  // dW/dr, 1/m^(d+1).
  Real derivative(Real r) const {
    const Real q = r / radius;
    if (q >= 1) return 0;
    const Real dw = q <= 0.5 ? 6 * (3 * q * q - 2 * q) : -6 * (1 - q) * (1 - q);
    return normalisation() * dw / radius;
  }
};

}  // namespace latmpm::optimize
