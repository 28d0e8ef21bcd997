// Uniform B-spline shape functions (Steffen et al. 2008; Taichi mpm99 uses the quadratic):
// smooth gradients, no cell-crossing error, wider stencils. On a sparse grid without
// boundary-modified splines the partition of unity holds everywhere material can be.
#pragma once
#include "mpm/stencil.hpp"

namespace latmpm::mpm {

// Quadratic: nodes base..base+2 with base = floor(x/h − ½), f = x/h − base ∈ [½, 3/2).
struct Bspline2Shape : ShapeFlags {
  static constexpr int nodes_per_axis = 3;
  static constexpr int reach_below = -1;
  static constexpr int reach_above = 2;
  static constexpr bool uses_half_size = false;
  static constexpr bool stretches_with_f = false;

  template <class T, class I>
  static void weights(T xi, T /*half*/, I& base, T* w, T* dw) {
    const T first = num::floor(xi - Real(0.5));
    base = num::to_int(first);
    const T f = xi - first;
    const T a = Real(1.5) - f, b = f - 1, c = f - Real(0.5);
    w[0] = Real(0.5) * a * a;
    w[1] = Real(0.75) - b * b;
    w[2] = Real(0.5) * c * c;
    dw[0] = -a;
    dw[1] = -2 * b;
    dw[2] = c;
  }
};

// Cubic: nodes base..base+3 with base = floor(x/h) − 1, t = x/h − base − 1 ∈ [0, 1).
struct Bspline3Shape : ShapeFlags {
  static constexpr int nodes_per_axis = 4;
  static constexpr int reach_below = -1;
  static constexpr int reach_above = 2;
  static constexpr bool uses_half_size = false;
  static constexpr bool stretches_with_f = false;

  template <class T, class I>
  static void weights(T xi, T /*half*/, I& base, T* w, T* dw) {
    const T cell = num::floor(xi);
    base = num::to_int(cell) - 1;
    const T t = xi - cell, t2 = t * t, t3 = t2 * t, s = 1 - t;
    constexpr Real sixth = Real(1) / 6;
    w[0] = sixth * s * s * s;
    w[1] = sixth * (3 * t3 - 6 * t2 + 4);
    w[2] = sixth * (-3 * t3 + 3 * t2 + 3 * t + 1);
    w[3] = sixth * t3;
    dw[0] = Real(-0.5) * s * s;
    dw[1] = Real(1.5) * t2 - 2 * t;
    dw[2] = Real(-1.5) * t2 + t + Real(0.5);
    dw[3] = Real(0.5) * t2;
  }
};

}  // namespace latmpm::mpm
