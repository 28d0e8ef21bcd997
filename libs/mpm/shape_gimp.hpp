// GIMP shape functions (Bardenhagen & Kober 2004; Paper A Sec. 2): the tent function
// averaged over the particle domain [x − l, x + l],
//   S_i(x) = 1/(2l) ∫ N((y − x_i)/h) dy = h/(2l) [Φ(u+) − Φ(u−)],   u± = (x ± l − x_i)/h,
//   dS_i/dx = 1/(2l) [N(u+) − N(u−)],
// with N(u) = max(0, 1 − |u|) and its antiderivative Φ(u) = ½ + c − ½ c|c|, c = clamp(u,−1,1).
// This one expression covers the three branches of the usual piecewise form.
//   uGIMP : l fixed (the paper's "GIMP"), l ≤ h/2 so three nodes per axis.
//   cpGIMP: l = l0 · F_aa per axis (domain stretched with the deformation along the axes),
//           l ≤ h so four nodes per axis.
#pragma once
#include <algorithm>

#include "mpm/stencil.hpp"

namespace latmpm::mpm {

namespace gimp_detail {
inline Real tent_antiderivative(Real u) {
  const Real c = std::clamp(u, Real(-1), Real(1));
  return Real(0.5) + c - Real(0.5) * c * std::abs(c);
}
inline Real tent(Real u) { return std::max(Real(0), 1 - std::abs(u)); }

// half: particle half-length in cell units, 0 < half ≤ (N − 2) / 2.
template <int N>
inline void weights(Real xi, Real half, int& base, Real* w, Real* dw) {
  base = floor_to_int(xi - half);
  const Real scale = Real(0.5) / half;
  for (int k = 0; k < N; ++k) {
    const Real up = xi + half - (base + k), um = xi - half - (base + k);
    w[k] = scale * (tent_antiderivative(up) - tent_antiderivative(um));
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
  static void weights_1d(Real xi, Real half, int& base, Real* w, Real* dw) {
    gimp_detail::weights<3>(xi, half, base, w, dw);
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
