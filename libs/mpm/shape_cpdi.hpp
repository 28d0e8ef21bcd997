// CPDI1 as a solver shape function (paper B Eq. 7; Sadeghirad, Brannon & Burghardt 2011):
//   S_I  = Σ_α w_α N̄_I(x_α),            w_α = ∫Q_α dV / V0,
//   ∇S_I = Σ_α F⁻ᵀ g_α N̄_I(x_α),        g_α = ∫Grad Q_α dV / V0,
// x_α = x_p + F (X_α − X_p) the domain's vertices convected with the particle's F (CPDI1,
// paper B Fig. 2), N̄_I the grid's trilinear tent functions. The reference integrals are
// exact (points/hexahedron.hpp) and the domain deforms affinely, so v = J V0 and the J of the
// convected integrals cancels against 1/v (cpdi.hpp, make_cpdi_domain).
//
// S_I is a sum of eight tensor products, not one, so its stencil is a dense 4×4×4 box of
// weights and gradients instead of Stencil<N>'s per-axis factors. The box starts one node
// below the particle's cell, so it holds every vertex whose cell lies within one cell of the
// particle's: a domain reaching at most one cell (h) from its centroid along each axis. A
// larger one (a coarse mesh on a fine grid, or a domain stretched past 2h) stops the run with
// a NumericalError naming the size; the bucket buffers' halo (particle_buckets.hpp) is what
// bounds it.
#pragma once
#include <cmath>
#include <string>
#include <type_traits>

#include "core/errors.hpp"
#include "mpm/node_lanes.hpp"
#include "mpm/particles.hpp"
#include "mpm/shape_flags.hpp"

namespace latmpm::mpm {

struct CpdiShape : ShapeFlags {
  static constexpr int nodes_per_axis = 4;
  static constexpr int reach_below = -1;  // lowest stencil node relative to the particle's cell
  static constexpr int reach_above = 2;   // highest
  static constexpr bool uses_half_size = false;
  static constexpr bool stretches_with_f = false;
  static constexpr bool uses_domain_vertices = true;
};

struct CpdiBoxStencil {
  static constexpr int n = CpdiShape::nodes_per_axis;
  int base[3];              // grid index of the box's first node per axis
  Real w[n * n * n];        // S_I of node base + (i, j, k) at (i·n + j)·n + k
  Real g[3][n * n * n];     // ∇S_I, 1/m, component by component
  static constexpr int index(int i, int j, int k) { return (i * n + j) * n + k; }
};

// Eq. 7 for particle p at its current position and F, on a grid of spacing h (m).
inline CpdiBoxStencil make_cpdi_box_stencil(const Particles& ps, size_t p, Real h) {
  constexpr int n = CpdiBoxStencil::n;
  const Real inv_h = 1 / h;
  const Vec3& x = ps.position[p];
  const Mat3& F = ps.deformation[p];
  const CpdiParticleDomain& d = ps.cpdi_domain[p];
  const Mat3 inverse_transpose = F.inverse().transpose();
  CpdiBoxStencil st;
  for (int a = 0; a < 3; ++a) st.base[a] = int(std::floor(x[a] * inv_h)) - 1;
  std::fill(std::begin(st.w), std::end(st.w), Real(0));
  for (auto& c : st.g) std::fill(std::begin(c), std::end(c), Real(0));
  for (int v = 0; v < 8; ++v) {
    const Vec3 xi = (x + F * d.col(v).head<3>()) * inv_h;
    const Vec3 grad = inverse_transpose * d.col(v).tail<3>();
    const Real weight = d(3, v);
    int local[3];
    Real frac[3];
    for (int a = 0; a < 3; ++a) {
      const Real cell = std::floor(xi[a]);
      local[a] = int(cell) - st.base[a];
      frac[a] = xi[a] - cell;
      if (!(local[a] >= 0 && local[a] <= n - 2))
        throw NumericalError("CPDI domain of point " + std::to_string(ps.id[p]) +
                             " reaches more than one cell (h) from its centre along axis " + std::to_string(a) +
                             "; use a finer mesh or a coarser grid");
    }
    for (int c = 0; c < 8; ++c) {
      const int i = local[0] + (c & 1), j = local[1] + ((c >> 1) & 1), k = local[2] + (c >> 2);
      const Real tent = ((c & 1) ? frac[0] : 1 - frac[0]) * ((c & 2) ? frac[1] : 1 - frac[1]) *
                        ((c & 4) ? frac[2] : 1 - frac[2]);
      const int e = CpdiBoxStencil::index(i, j, k);
      st.w[e] += weight * tent;
      for (int a = 0; a < 3; ++a) st.g[a][e] += grad[a] * tent;
    }
  }
  return st;
}

// P2G of one particle: node += S_I a + ∂xS_I fx + ∂yS_I fy + ∂zS_I fz over the box (the
// lane vectors of scatter_bucket); Force = false skips the gradient terms.
template <bool Force, int RowStrideI, int RowStrideJ>
inline void scatter_cpdi(const CpdiBoxStencil& st, Real* first, const NodeLanes& a, const NodeLanes& fx,
                         const NodeLanes& fy, const NodeLanes& fz) {
  constexpr int n = CpdiBoxStencil::n;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const int e = CpdiBoxStencil::index(i, j, k);
        Real* node = first + i * RowStrideI + j * RowStrideJ + k * lane::count;
        NodeLanes add = st.w[e] * a;
        if constexpr (Force) add += st.g[0][e] * fx + st.g[1][e] * fy + st.g[2][e] * fz;
        store_lanes(node, load_lanes(node) + add);
      }
}

}  // namespace latmpm::mpm
