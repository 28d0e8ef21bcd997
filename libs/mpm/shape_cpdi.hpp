// CPDI1 as a solver shape function (paper B Eq. 7; Sadeghirad, Brannon & Burghardt 2011):
//   S_I  = Σ_α w_α N̄_I(x_α),            w_α = ∫Q_α dV / V0,
//   ∇S_I = Σ_α F⁻ᵀ g_α N̄_I(x_α),        g_α = ∫Grad Q_α dV / V0,
// x_α = x_p + F (X_α − X_p) the domain's vertices convected with the particle's F (CPDI1,
// paper B Fig. 2), N̄_I the grid's trilinear tent functions. The reference integrals are
// exact (points/hexahedron.hpp) and the domain deforms affinely, so v = J V0 and the J of the
// convected integrals cancels against 1/v (cpdi.hpp, make_cpdi_domain).
//
// S_I is a sum of eight tensor products, one per vertex, not one, so its stencil is a dense
// 4×4×4 box of weights and gradients instead of Stencil<N>'s per-axis factors. The box
// starts one node below the particle's cell, so it holds every vertex whose cell lies within
// one cell of the particle's: a domain reaching at most one cell (h) from its centroid along
// each axis, which is what the bucket buffers' halo (particle_buckets.hpp) holds.
//
// A larger domain (a coarse mesh on a fine grid, a rim domain stretched by barrelling) is
// legal in the method: each vertex still reaches only the 8 nodes of its own cell. Such a
// stencil is "wide": its box is left empty and its eight vertex stencils (cell, fractions,
// w_α, F⁻ᵀ g_α) are used instead, node by node on the sparse grid, outside the bucket
// buffers (step_stages.hpp: the scatter adds wide points after the buckets, serially in
// particle order, and the gather reads their nodes from the grid; prepare_grid activates
// their blocks). No node is dropped and the functions are the same, so Σ S_I = 1 and linear
// completeness hold for any domain size.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
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

// One convected vertex α of a domain: its grid cell, its place in the cell (fractions of h),
// w_α and F⁻ᵀ g_α (1/m).
struct CpdiVertexTent {
  int cell[3];
  Real frac[3];
  Real weight;
  Real grad[3];
};

struct CpdiBoxStencil {
  static constexpr int n = CpdiShape::nodes_per_axis;
  int base[3];              // grid index of the box's first node per axis
  Real w[n * n * n];        // S_I of node base + (i, j, k) at (i·n + j)·n + k
  Real g[3][n * n * n];     // ∇S_I, 1/m, component by component
  // True when a vertex lies outside the box: then w and g are zero and the functions are
  // the vertex tents' (for_each_cpdi_vertex_node).
  bool wide = false;
  CpdiVertexTent vertex[8];
  static constexpr int index(int i, int j, int k) { return (i * n + j) * n + k; }
};

// Calls fn(i, j, k, S, ∂xS, ∂yS, ∂zS) for the 8 nodes of each vertex's cell: the terms of
// Eq. 7 one vertex at a time (a node shared by several vertices is called once per vertex).
// Grid coordinates; any domain size.
template <class Fn>
inline void for_each_cpdi_vertex_node(const CpdiBoxStencil& st, Fn&& fn) {
  for (const CpdiVertexTent& t : st.vertex)
    for (int c = 0; c < 8; ++c) {
      const Real tent = ((c & 1) ? t.frac[0] : 1 - t.frac[0]) * ((c & 2) ? t.frac[1] : 1 - t.frac[1]) *
                        ((c & 4) ? t.frac[2] : 1 - t.frac[2]);
      fn(t.cell[0] + (c & 1), t.cell[1] + ((c >> 1) & 1), t.cell[2] + (c >> 2), t.weight * tent, t.grad[0] * tent,
         t.grad[1] * tent, t.grad[2] * tent);
    }
}

// Vertex v of particle p's domain convected by F, in grid coordinates (cells of 1/inv_h).
inline Vec3 cpdi_vertex_in_cells(const Vec3& x, const Mat3& F, const CpdiParticleDomain& d, int v, Real inv_h) {
  return (x + F * d.col(v).head<3>()) * inv_h;
}

// A vertex in cell `vertex_cell` lies outside the 4-node box of a point in `point_cell`
// (along one axis): the domain is "wide" and is scattered vertex by vertex on the grid.
inline bool cpdi_vertex_outside_box(int vertex_cell, int point_cell) {
  return vertex_cell < point_cell - 1 || vertex_cell > point_cell + CpdiBoxStencil::n - 3;
}

// Eq. 7 for particle p at its current position and F, on a grid of spacing h (m).
inline CpdiBoxStencil make_cpdi_box_stencil(const Particles& ps, size_t p, Real h) {
  const Real inv_h = 1 / h;
  const Vec3& x = ps.position[p];
  const Mat3 F = ps.deformation[p].cast<Real>();
  const CpdiParticleDomain& d = ps.cpdi_domain[p];
  const Mat3 inverse_transpose = F.inverse().transpose();
  CpdiBoxStencil st;
  for (int a = 0; a < 3; ++a) st.base[a] = int(std::floor(x[a] * inv_h)) - 1;
  std::fill(std::begin(st.w), std::end(st.w), Real(0));
  for (auto& c : st.g) std::fill(std::begin(c), std::end(c), Real(0));
  for (int v = 0; v < 8; ++v) {
    const Vec3 xi = cpdi_vertex_in_cells(x, F, d, v, inv_h);
    const Vec3 grad = inverse_transpose * d.col(v).tail<3>();
    CpdiVertexTent& t = st.vertex[v];
    t.weight = d(3, v);
    for (int a = 0; a < 3; ++a) {
      if (!(std::abs(xi[a]) < Real(1 << 30)))
        throw NumericalError("CPDI domain of point " + std::to_string(ps.id[p]) + " has a vertex that is not finite or far off the grid");
      const Real cell = std::floor(xi[a]);
      t.cell[a] = int(cell);
      t.frac[a] = xi[a] - cell;
      t.grad[a] = grad[a];
      if (cpdi_vertex_outside_box(t.cell[a], st.base[a] + 1)) st.wide = true;
    }
  }
  if (st.wide) return st;  // the vertex tents only (for_each_cpdi_vertex_node)
  for_each_cpdi_vertex_node(st, [&](int i, int j, int k, Real w, Real gx, Real gy, Real gz) {
    const int e = CpdiBoxStencil::index(i - st.base[0], j - st.base[1], k - st.base[2]);
    st.w[e] += w;
    st.g[0][e] += gx, st.g[1][e] += gy, st.g[2][e] += gz;
  });
  return st;
}

// The lowest and highest cell of the particle's convected vertices, per axis (grid
// coordinates): prepare_grid activates the blocks of a wide domain's nodes from these.
inline void cpdi_vertex_cell_range(const Particles& ps, size_t p, Real h, int lo[3], int hi[3]) {
  const Vec3& x = ps.position[p];
  const Mat3 F = ps.deformation[p].cast<Real>();
  const CpdiParticleDomain& d = ps.cpdi_domain[p];
  const Real inv_h = 1 / h;
  for (int a = 0; a < 3; ++a) lo[a] = std::numeric_limits<int>::max(), hi[a] = std::numeric_limits<int>::min();
  for (int v = 0; v < 8; ++v) {
    const Vec3 xi = cpdi_vertex_in_cells(x, F, d, v, inv_h);
    for (int a = 0; a < 3; ++a) {
      if (!(std::abs(xi[a]) < Real(1 << 30))) continue;  // a non-finite vertex: the stencil reports it
      const int cell = int(std::floor(xi[a]));
      lo[a] = std::min(lo[a], cell);
      hi[a] = std::max(hi[a], cell);
    }
  }
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
        NodeLanes add = scaled(st.w[e], a);
        if constexpr (Force) add += plus_scaled(plus_scaled(scaled(st.g[0][e], fx), st.g[1][e], fy), st.g[2][e], fz);
        store_lanes(node, load_lanes(node) + add);
      }
}

}  // namespace latmpm::mpm
