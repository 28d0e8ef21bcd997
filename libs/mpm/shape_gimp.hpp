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
#include <algorithm>

#include "mpm/stencil.hpp"

namespace latmpm::mpm {

namespace gimp_detail {
inline Real tent(Real u) { return std::max(Real(0), 1 - std::abs(u)); }

// Φ(b) − Φ(a) for a ≤ b, written as a product wherever both ends lie on one side of the
// node: near the edge of the support the weight is tiny, and the plain difference of two
// values close to 1 would leave only round-off there — a node with a round-off mass and a
// consistent force accelerates without bound.
inline Real tent_integral(Real a, Real b) {
  const Real ca = std::clamp(a, Real(-1), Real(1)), cb = std::clamp(b, Real(-1), Real(1));
  if (ca >= 0) return Real(0.5) * (cb - ca) * (2 - ca - cb);  // [(1−ca)² − (1−cb)²]/2
  if (cb <= 0) return Real(0.5) * (cb - ca) * (2 + ca + cb);  // [(1+cb)² − (1+ca)²]/2
  return 1 - Real(0.5) * ((1 - cb) * (1 - cb) + (1 + ca) * (1 + ca));
}

// half: particle half-length in cell units, 0 < half ≤ (N − 2) / 2.
template <int N>
inline void weights(Real xi, Real half, int& base, Real* w, Real* dw) {
  base = floor_to_int(xi - half);
  const Real scale = Real(0.5) / half;
  for (int k = 0; k < N; ++k) {
    const Real up = xi + half - (base + k), um = xi - half - (base + k);
    w[k] = scale * tent_integral(um, up);
    dw[k] = scale * (tent(up) - tent(um));
  }
}
}  // namespace gimp_detail

struct UgimpShape {
  static constexpr int nodes_per_axis = 3;
  static constexpr int reach_below = -1;
  static constexpr int reach_above = 2;
  static constexpr bool uses_half_size = true;
  static constexpr bool stretches_with_f = false;
  static constexpr Real max_half = 0.5;  // cell units
  // The same integrals in closed form for a domain no wider than a cell, without branches
  // (the hot path): with the domain [a, b] relative to the first node, a ∈ [0, 1),
  // b = a + 2l < 2, and e = max(b − 1, 0) its overhang past the middle node,
  //   2l S0 = (1−a)²/2 − max(1−b, 0)²/2,   2l S2 = e²/2,   S1 = 1 − S0 − S2,
  //   2l S0' = max(1−b, 0) − (1−a),        2l S2' = e,      S1' = −S0' − S2'.
  // Each is a square or a difference of non-negative terms that vanish together, so small
  // weights near the edge of the support stay accurate.
  static void weights_1d(Real xi, Real half, int& base, Real* w, Real* dw) {
    const Real lo = xi - half;
    base = floor_to_int(lo);
    const Real a = lo - base, b = a + 2 * half;
    const Real inv_width = Real(0.5) / half;
    const Real left = 1 - a, short_of_middle = std::max(1 - b, Real(0)), e = std::max(b - 1, Real(0));
    w[0] = Real(0.5) * inv_width * (left * left - short_of_middle * short_of_middle);
    w[2] = Real(0.5) * inv_width * e * e;
    w[1] = 1 - w[0] - w[2];
    dw[0] = inv_width * (short_of_middle - left);
    dw[2] = inv_width * e;
    dw[1] = -dw[0] - dw[2];
  }
};

struct CpgimpShape {
  static constexpr int nodes_per_axis = 4;
  static constexpr int reach_below = -1;
  static constexpr int reach_above = 3;
  static constexpr bool uses_half_size = true;
  static constexpr bool stretches_with_f = true;
  static constexpr Real max_half = 1.0;  // cell units
  static void weights_1d(Real xi, Real half, int& base, Real* w, Real* dw) {
    gimp_detail::weights<4>(xi, half, base, w, dw);
  }
};

}  // namespace latmpm::mpm
