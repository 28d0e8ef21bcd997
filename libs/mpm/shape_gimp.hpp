// GIMP shape functions (Bardenhagen & Kober 2004; Paper A Sec. 2): the tent function
// averaged over the particle domain [x − l, x + l],
//   S_i(x) = 1/(2l) ∫ N((y − x_i)/h) dy = h/(2l) [Φ(u+) − Φ(u−)],   u± = (x ± l − x_i)/h,
//   dS_i/dx = 1/(2l) [N(u+) − N(u−)],
// with N(u) = max(0, 1 − |u|) and Φ its antiderivative. This one expression covers the three
// branches of the usual piecewise form.
//   uGIMP : l fixed (the paper's "GIMP"), l ≤ h/2 so three nodes per axis.
//   cpGIMP: l = l0 · F_aa per axis (domain stretched with the deformation along the axes),
//           l ≤ h so four nodes per axis.
#pragma once
#include "mpm/stencil.hpp"

namespace latmpm::mpm {

namespace gimp_detail {
template <class T>
inline T tent(T u) { return num::max(num::constant<T>(0), 1 - num::abs(u)); }

// Φ(b) − Φ(a) for a ≤ b, written as a product wherever both ends lie on one side of the
// node: near the edge of the support the weight is tiny, and the plain difference of two
// values close to 1 would leave only round-off there — a node with a round-off mass and a
// consistent force accelerates without bound.
template <class T>
inline T tent_integral(T a, T b) {
  const T ca = num::clamp(a, -1, 1), cb = num::clamp(b, -1, 1);
  const T right = Real(0.5) * (cb - ca) * (2 - ca - cb);  // both ≥ 0: [(1−ca)² − (1−cb)²]/2
  const T left = Real(0.5) * (cb - ca) * (2 + ca + cb);   // both ≤ 0: [(1+cb)² − (1+ca)²]/2
  const T across = 1 - Real(0.5) * ((1 - cb) * (1 - cb) + (1 + ca) * (1 + ca));
  return ca >= 0 ? right : (cb <= 0 ? left : across);
}
}  // namespace gimp_detail

struct UgimpShape : ShapeFlags {
  static constexpr int nodes_per_axis = 3;
  static constexpr int reach_below = -1;
  static constexpr int reach_above = 2;
  static constexpr bool uses_half_size = true;
  static constexpr bool stretches_with_f = false;
  static constexpr Real max_half = 0.5;  // cell units
  static constexpr bool trims_zero_planes = true;  // S2 = S2' = 0 while e = 0 (stencil.hpp)

  // The integrals in closed form for a domain no wider than a cell, without branches (the
  // hot path): with the domain [a, b] relative to the first node, a ∈ [0, 1), b = a + 2l < 2,
  // and e = max(b − 1, 0) its overhang past the middle node,
  //   2l S0 = (1−a)²/2 − max(1−b, 0)²/2,   2l S2 = e²/2,   S1 = 1 − S0 − S2,
  //   2l S0' = max(1−b, 0) − (1−a),        2l S2' = e,      S1' = −S0' − S2'.
  // Each is a square or a difference of non-negative terms that vanish together, so small
  // weights near the edge of the support stay accurate.
  template <class T, class I>
  static void weights(T xi, T half, I& base, T* w, T* dw) {
    const T lo = xi - half;
    const T first = num::floor(lo);
    base = num::to_int(first);
    const T a = lo - first, b = a + 2 * half;
    const T inv_width = Real(0.5) / half;
    const T left = 1 - a, short_of_middle = num::max(1 - b, num::constant<T>(0));
    const T e = num::max(b - 1, num::constant<T>(0));
    w[0] = Real(0.5) * inv_width * (left * left - short_of_middle * short_of_middle);
    w[2] = Real(0.5) * inv_width * e * e;
    w[1] = 1 - w[0] - w[2];
    dw[0] = inv_width * (short_of_middle - left);
    dw[2] = inv_width * e;
    dw[1] = -dw[0] - dw[2];
  }
};

struct CpgimpShape : ShapeFlags {
  static constexpr int nodes_per_axis = 4;
  static constexpr int reach_below = -1;
  static constexpr int reach_above = 3;
  static constexpr bool uses_half_size = true;
  static constexpr bool stretches_with_f = true;
  static constexpr Real max_half = 1.0;  // cell units

  // The general form above, node by node (the domain may span up to two cells).
  template <class T, class I>
  static void weights(T xi, T half, I& base, T* w, T* dw) {
    const T first = num::floor(xi - half);
    base = num::to_int(first);
    const T scale = Real(0.5) / half;
    for (int k = 0; k < nodes_per_axis; ++k) {
      const T node = first + Real(k);
      const T up = xi + half - node, um = xi - half - node;
      w[k] = scale * gimp_detail::tent_integral(um, up);
      dw[k] = scale * (gimp_detail::tent(up) - gimp_detail::tent(um));
    }
  }
};

}  // namespace latmpm::mpm
