// Linear (tent) shape functions of the original MPM (Sulsky et al. 1994): S(ξ) = 1 − |ξ|,
// two nodes per axis. Gradients jump where a particle crosses a cell face (the cell-crossing
// error GIMP and B-splines remove).
#pragma once
#include "mpm/stencil.hpp"

namespace latmpm::mpm {

struct LinearShape : ShapeFlags {
  static constexpr int nodes_per_axis = 2;
  static constexpr int reach_below = 0;  // lowest stencil node relative to the particle's cell
  static constexpr int reach_above = 1;  // highest stencil node relative to the particle's cell
  static constexpr bool uses_half_size = false;
  static constexpr bool stretches_with_f = false;

  template <class T, class I>
  static void weights(T xi, T /*half*/, I& base, T* w, T* dw) {
    const T cell = num::floor(xi);
    base = num::to_int(cell);
    const T f = xi - cell;  // in [0, 1)
    w[0] = 1 - f;
    w[1] = f;
    dw[0] = num::constant<T>(-1);
    dw[1] = num::constant<T>(1);
  }
};

}  // namespace latmpm::mpm
