// The per-particle stencil every shape function produces: for each axis the first node
// index and the 1D weights and derivatives of the N nodes from there. The 3D shape function
// is the tensor product S_i = Sx·Sy·Sz and ∇S_i = (Sx'·Sy·Sz, Sx·Sy'·Sz, Sx·Sy·Sz'), so
// P2G and G2P share one small stencil instead of N³ stored weights.
#pragma once
#include <cmath>

#include "mpm/real.hpp"

namespace latmpm::mpm {

template <int N>
struct Stencil {
  static constexpr int nodes_per_axis = N;
  int base[3];     // node index (grid coordinates) of the stencil's first node per axis
  Real w[3][N];    // 1D weights, dimensionless
  Real dw[3][N];   // 1D derivatives dS/dx, 1/m
};

// Integer part towards −∞ that is exact for the grid coordinates the solver uses.
inline int floor_to_int(Real x) { return static_cast<int>(std::floor(x)); }

// Fills a Stencil from a 1D policy applied per axis. Shape::weights_1d(xi, half, base, w,
// dw) receives the coordinate in cell units (x/h) and the half-size in cell units, and
// returns the first node and weights with derivatives in cell units (multiplied by 1/h here).
template <class Shape>
inline Stencil<Shape::nodes_per_axis> make_stencil(const Vec3& x, const Vec3& half, Real inv_h) {
  Stencil<Shape::nodes_per_axis> s;
  for (int a = 0; a < 3; ++a) {
    Shape::weights_1d(x[a] * inv_h, half[a] * inv_h, s.base[a], s.w[a], s.dw[a]);
    for (int k = 0; k < Shape::nodes_per_axis; ++k) s.dw[a][k] *= inv_h;
  }
  return s;
}

}  // namespace latmpm::mpm
