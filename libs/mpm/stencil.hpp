// The per-particle stencil every shape function produces: the first node index per axis,
// and for each of the N nodes along an axis the 1D weight and derivative — kept for the
// three axes side by side in one small SIMD value, so a policy computes all three axes in
// one pass. The 3D shape function is the tensor product S = Sx·Sy·Sz and
// ∇S = (Sx'·Sy·Sz, Sx·Sy'·Sz, Sx·Sy·Sz'), so P2G and G2P share one small stencil instead of
// N³ stored weights.
//
// Shape policies write their 1D formulas once, as templates over the number type T: plain
// Real (tests, reference) or Axes (x, y, z and one spare lane), with the helpers of simd.hpp.
#pragma once
#include "mpm/real.hpp"
#include "mpm/simd.hpp"

namespace latmpm::mpm {

inline int floor_to_int(Real x) { return num::floor_to_int(x); }

template <int N>
struct Stencil {
  static constexpr int nodes_per_axis = N;
  int base[3];  // node index (grid coordinates) of the stencil's first node per axis
  Axes w[N];    // w[k][a]: weight of the k-th node along axis a, dimensionless
  Axes dw[N];   // dw[k][a]: its derivative dS/dx_a, 1/m
};

// Fills a Stencil from a shape policy: Shape::weights(xi, half, base, w, dw) receives the
// coordinates in cell units (x/h) and the half-sizes in cell units, and returns the first
// nodes and the weights with derivatives in cell units (multiplied by 1/h here).
template <class Shape>
inline Stencil<Shape::nodes_per_axis> make_stencil(const Vec3& x, const Vec3& half, Real inv_h) {
  constexpr int N = Shape::nodes_per_axis;
  Stencil<N> s;
  // The spare lane gets a harmless position and half-size (no division by zero).
  const Axes xi = {x[0] * inv_h, x[1] * inv_h, x[2] * inv_h, Real(0.5)};
  const Axes hv = {half[0] * inv_h, half[1] * inv_h, half[2] * inv_h, Real(0.25)};
  AxesInt base;
  Shape::weights(xi, hv, base, s.w, s.dw);
  for (int a = 0; a < 3; ++a) s.base[a] = base[a];
  for (int k = 0; k < N; ++k) s.dw[k] *= inv_h;
  return s;
}

}  // namespace latmpm::mpm
