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
#include <type_traits>

#include "mpm/real.hpp"
#include "mpm/shape_flags.hpp"
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

// A stencil with its trailing node planes of zero weight cut off, per axis. GIMP's outer
// nodes carry weight only while the particle domain overhangs the node before them: uGIMP's
// third node per axis is exactly zero whenever e = 0 (shape_gimp.hpp), half of all positions
// with two points per cell, so on average 2.5³ ≈ 15.6 of the 27 nodes carry weight. The
// node loops stop at count[a]; the planes left out have S = S' = 0 exactly, so they would
// only add exact zeros (results are bit-identical either way).
template <int N>
struct TrimmedStencil : Stencil<N> {
  int count[3];  // nodes per axis up to the last one with a non-zero weight or derivative
};

template <int N>
inline TrimmedStencil<N> trim_zero_planes(const Stencil<N>& s) {
  TrimmedStencil<N> t;
  static_cast<Stencil<N>&>(t) = s;
  using Mask = decltype(s.w[0] == s.w[0]);  // per axis −1 (true) or 0
  Mask zero_tail = ~Mask{};
  Mask count = Mask{} + N;
  for (int k = N - 1; k >= 2; --k) {  // a trimmed plane adds −1; two nodes always stay
    zero_tail &= (s.w[k] == 0) & (s.dw[k] == 0);
    count += zero_tail;
  }
  for (int a = 0; a < 3; ++a) t.count[a] = int(count[a]);
  return t;
}

// Calls f(std::integral_constant<int, n>()) for 2 ≤ n ≤ N: a node loop bounded by a count
// becomes one of N − 1 loops with a fixed trip count (unrolled by the compiler).
template <int N, class F>
[[gnu::always_inline]] inline void with_trip_count(int n, F&& f) {
  if constexpr (N > 2)
    if (n < N) return with_trip_count<N - 1>(n, f);
  f(std::integral_constant<int, N>());
}

// Nodes along axis a the node loops visit: all N of a plain stencil (a compile-time
// constant: fixed trip counts), count[a] of a trimmed one.
template <int N>
constexpr int nodes_along(const Stencil<N>&, int) { return N; }
template <int N>
inline int nodes_along(const TrimmedStencil<N>& s, int a) {
  return s.count[a];
}

// Shape policies whose outer nodes are often exactly zero set ShapeFlags::trims_zero_planes
// and get TrimmedStencils.

}  // namespace latmpm::mpm
