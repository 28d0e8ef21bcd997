// DDMP's smoothed gradient evaluated on the grid (Paper A Eq. 4, the paper's own practice):
// the per-particle sum over 4×4×4 nodes of Eq. 7 is split into a particle part on the
// particle's 8 cell corners and a grid pass over the cells of Ω.
//
// Force (Eq. 6 with Eq. 7's smoothed part):
//   −Σ_p V_p σ_p (1 − α_p) Σ_j S̃_j(x_p)/V_j ∫_Ω S_j ∇S_i dV = −Σ_j σ^d_j ∫_Ω S_j ∇S_i dV,
//   σ^d_j V_j = Σ_p (1 − α_p) S̃_j(x_p) V_p σ_p          (P2G, 6 values per node),
// Velocity gradient:
//   Σ_i v_i ⊗ (1 − α_p) Σ_j S̃_j/V_j ∫_Ω S_j ∇S_i = (1 − α_p) Σ_j S̃_j(x_p) L_j,
//   L_j = (1/V_j) Σ_i v_i ⊗ ∫_Ω S_j ∇S_i dV                (grid pass, 9 values per node),
// with S̃_j, V_j and Ω as in shape_ddmp.hpp (make_ddmp_corner_stencil gives (1 − α) S̃_j).
// Both are the per-particle ∇̄S regrouped, so results agree with DdmpShape to round-off;
// the cost per particle drops from two dense 64-node passes to 8-corner ones.
//
// ∫_Ω S_j ∇S_i dV = Σ_{cells e of Ω with corners j and i} h² T[j − e][i − e], T the constant
// table of ddmp_cell_integrals(). The grid passes are written node by node (each node sums
// over the Ω cells around it, in a fixed order, and writes only itself): deterministic for
// any thread count. The nodal values live beside the grid's 8 lanes, in DdmpNodalValues,
// allocated only for DDMP-on-grid runs.
#pragma once
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "mpm/bucket_buffer.hpp"
#include "mpm/cell_occupancy.hpp"
#include "mpm/shape_ddmp.hpp"
#include "mpm/sparse_grid.hpp"

namespace latmpm::mpm {

// Per grid node, in block order like the grid (block · 64 + node):
//   after P2G: M_j = Σ_p (1 − α_p) S̃_j(x_p) (−V_p σ_p), Voigt order xx yy zz yz xz xy
//   (6 values); after ddmp_nodal_stress: M_j · 8/(count_j h) = −σ^d_j h², since
//   ∫_Ω S_j ∇S_i dV = h² Σ_e T and V_j = count_j h³/8;
//   before G2P: L_j, row-major (9 values).
struct DdmpNodalValues {
  static constexpr int count = BucketBuffer::ddmp_values;
  std::vector<Real> values;
  std::vector<std::array<int, 27>> neighbours;  // per block: block (dx, dy, dz) ∈ {−1, 0, 1}³ away, −1 inactive
  std::vector<uint8_t> omega;                   // per block, 64 cells (named by their lowest node): in Ω

  Real* node(size_t block, int n) { return values.data() + (block * SparseGrid::nodes_per_block + size_t(n)) * count; }
  const Real* node(size_t block, int n) const {
    return values.data() + (block * SparseGrid::nodes_per_block + size_t(n)) * count;
  }
};

namespace ddmp_grid_detail {
constexpr int bw = SparseGrid::block_width;
inline int neighbour_index(int dx, int dy, int dz) { return (dx + 1) * 9 + (dy + 1) * 3 + (dz + 1); }

// The Ω flags of the cells at local coordinates −1 … 3 around a block (index local + 1).
struct CellHalo {
  uint8_t in_omega[5][5][5];
};
inline void load_cells(const DdmpNodalValues& nv, size_t block, CellHalo& halo) {
  for (int i = -1; i < bw; ++i)
    for (int j = -1; j < bw; ++j)
      for (int k = -1; k < bw; ++k) {
        const int di = floor_div(i, bw), dj = floor_div(j, bw), dk = floor_div(k, bw);
        const int nb = nv.neighbours[block][size_t(neighbour_index(di, dj, dk))];
        halo.in_omega[i + 1][j + 1][k + 1] =
            nb < 0 ? 0
                   : nv.omega[size_t(nb) * SparseGrid::nodes_per_block +
                              size_t(((i - bw * di) * bw + (j - bw * dj)) * bw + (k - bw * dk))];
      }
}

// `Components` values of the nodes at local coordinates −1 … 4 around a block (index
// local + 1): value c of node n of block b is get(b, n)[c]; zero in inactive blocks.
template <int Components>
struct NodeHalo {
  Real v[6][6][6][Components];
};
template <int Components, class Get>
void load_nodes(const DdmpNodalValues& nv, size_t block, Get get, NodeHalo<Components>& halo) {
  for (int i = -1; i <= bw; ++i)
    for (int j = -1; j <= bw; ++j)
      for (int k = -1; k <= bw; ++k) {
        const int di = floor_div(i, bw), dj = floor_div(j, bw), dk = floor_div(k, bw);
        const int nb = nv.neighbours[block][size_t(neighbour_index(di, dj, dk))];
        Real* out = halo.v[i + 1][j + 1][k + 1];
        if (nb < 0) {
          for (int c = 0; c < Components; ++c) out[c] = 0;
          continue;
        }
        const Real* in = get(size_t(nb), ((i - bw * di) * bw + (j - bw * dj)) * bw + (k - bw * dk));
        for (int c = 0; c < Components; ++c) out[c] = in[c];
      }
}

// Ω cells around node (li, lj, lk) of the block (local 0 … 3).
inline int omega_cells_around(const CellHalo& cells, int li, int lj, int lk) {
  int n = 0;
  for (int l = 0; l < 8; ++l) n += cells.in_omega[li + 1 - (l >> 2)][lj + 1 - ((l >> 1) & 1)][lk + 1 - (l & 1)];
  return n;
}

// 8/(n h) for a node with n Ω cells around it (V_j = n h³/8, and the table's h²), 0 if none.
inline Real nodal_volume_scale(int n, Real h) { return n > 0 ? Real(8) / (Real(n) * h) : Real(0); }

// For node (li, lj, lk) of the block: fn(self, other, x, y, z) for each Ω cell e around it,
// the node being corner `self` of e, and each corner `other` of e at halo index (x, y, z)
// (NodeHalo's indexing); the pair's cell integral is T[self][other] or T[other][self].
template <class Fn>
[[gnu::always_inline]] inline void for_each_omega_corner_pair(const CellHalo& cells, int li, int lj, int lk, Fn&& fn) {
  for (int self = 0; self < 8; ++self) {  // node = cell e's lowest node + corner offset
    const int ex = li + 1 - (self >> 2), ey = lj + 1 - ((self >> 1) & 1), ez = lk + 1 - (self & 1);  // halo indices
    if (!cells.in_omega[ex][ey][ez]) continue;
    for (int other = 0; other < 8; ++other) fn(self, other, ex + (other >> 2), ey + ((other >> 1) & 1), ez + (other & 1));
  }
}
}  // namespace ddmp_grid_detail

// Sizes and zeroes the nodal values for the grid's active blocks and finds each block's
// neighbours and cells of Ω (Σ V0 ≥ h³/2: the same test as fill_occupancy).
inline void prepare_ddmp_nodal_values(const SparseGrid& grid, const std::vector<Real>& cell_volume, Real h,
                                      DdmpNodalValues& nv) {
  using namespace ddmp_grid_detail;
  const size_t blocks = grid.block_count();
  nv.values.assign(blocks * SparseGrid::nodes_per_block * DdmpNodalValues::count, Real(0));
  nv.neighbours.resize(blocks);
  nv.omega.resize(blocks * SparseGrid::nodes_per_block);
  const Real half_cell = Real(0.5) * h * h * h;
  tbb::parallel_for(size_t(0), blocks, [&](size_t b) {
    const auto c = grid.coord(b);
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz)
          nv.neighbours[b][size_t(neighbour_index(dx, dy, dz))] = grid.find(c[0] + dx, c[1] + dy, c[2] + dz);
    for (int n = 0; n < SparseGrid::nodes_per_block; ++n)
      nv.omega[b * SparseGrid::nodes_per_block + size_t(n)] =
          cell_volume[b * SparseGrid::nodes_per_block + size_t(n)] >= half_cell;
  });
}

// Zeroes every node's values (before a scatter that maps the stress again).
inline void clear_ddmp_nodal_values(DdmpNodalValues& nv) { std::fill(nv.values.begin(), nv.values.end(), Real(0)); }

// The mapped −(1 − α) S̃ V σ of each node j into M_j · 8/(count_j h), count_j the Ω cells
// around j (V_j = count_j h³/8): then −Σ_j σ^d_j ∫_Ω S_j ∇S_i dV = Σ_j (that) Σ_e T[..].
inline void ddmp_nodal_stress(const SparseGrid& grid, Real h, DdmpNodalValues& nv) {
  using namespace ddmp_grid_detail;
  tbb::parallel_for(size_t(0), grid.block_count(), [&](size_t b) {
    CellHalo cells;
    load_cells(nv, b, cells);
    for (int i = 0; i < bw; ++i)
      for (int j = 0; j < bw; ++j)
        for (int k = 0; k < bw; ++k) {
          Real* m = nv.node(b, (i * bw + j) * bw + k);
          const Real scale = nodal_volume_scale(omega_cells_around(cells, i, j, k), h);
          for (int c = 0; c < 6; ++c) m[c] *= scale;
        }
  });
}

// f_i += Σ_{Ω cells e around i} Σ_{corners j of e} s_j T[j − e][i − e], s_j the values of
// ddmp_nodal_stress (a symmetric tensor in Voigt order): the smoothed part of Eq. 6's force,
// into the grid's force lanes.
inline void add_ddmp_smoothed_force(SparseGrid& grid, const DdmpNodalValues& nv) {
  using namespace ddmp_grid_detail;
  const auto& table = ddmp_cell_integrals();
  tbb::parallel_for(size_t(0), grid.block_count(), [&](size_t b) {
    CellHalo cells;
    load_cells(nv, b, cells);
    NodeHalo<6> s;
    load_nodes<6>(nv, b, [&](size_t nb, int n) { return nv.node(nb, n); }, s);
    for (int i = 0; i < bw; ++i)
      for (int j = 0; j < bw; ++j)
        for (int k = 0; k < bw; ++k) {
          Real f[3] = {0, 0, 0};
          for_each_omega_corner_pair(cells, i, j, k, [&](int self, int other, int x, int y, int z) {
            const Real* sj = s.v[x][y][z];  // node i = self, node j = other: T[j][i]
            const Vec3& g = table[size_t(other)][size_t(self)];
            f[0] += sj[0] * g[0] + sj[5] * g[1] + sj[4] * g[2];
            f[1] += sj[5] * g[0] + sj[1] * g[1] + sj[3] * g[2];
            f[2] += sj[4] * g[0] + sj[3] * g[1] + sj[2] * g[2];
          });
          Real* node = grid.block(b) + SparseGrid::node_offset(i, j, k);
          for (int a = 0; a < 3; ++a) node[lane::force + a] += f[a];
        }
  });
}

// L_j = (1/V_j) Σ_i v_i ⊗ ∫_Ω S_j ∇S_i dV from the grid velocities in lanes
// velocity_lane … + 2, into the nodal values (row-major).
inline void ddmp_nodal_velocity_gradient(const SparseGrid& grid, int velocity_lane, Real h, DdmpNodalValues& nv) {
  using namespace ddmp_grid_detail;
  const auto& table = ddmp_cell_integrals();
  tbb::parallel_for(size_t(0), grid.block_count(), [&](size_t b) {
    CellHalo cells;
    load_cells(nv, b, cells);
    NodeHalo<3> v;
    load_nodes<3>(nv, b, [&](size_t nb, int n) { return grid.block(nb) + n * lane::count + velocity_lane; }, v);
    for (int i = 0; i < bw; ++i)
      for (int j = 0; j < bw; ++j)
        for (int k = 0; k < bw; ++k) {
          Real L[9] = {};
          for_each_omega_corner_pair(cells, i, j, k, [&](int self, int other, int x, int y, int z) {
            const Real* vi = v.v[x][y][z];  // node j = self, node i = other: T[j][i]
            const Vec3& g = table[size_t(self)][size_t(other)];
            for (int r = 0; r < 3; ++r)
              for (int c = 0; c < 3; ++c) L[r * 3 + c] += vi[r] * g[c];
          });
          Real* out = nv.node(b, (i * bw + j) * bw + k);
          const Real scale = nodal_volume_scale(omega_cells_around(cells, i, j, k), h);
          for (int c = 0; c < 9; ++c) out[c] = scale * L[c];
        }
  });
}

// --- The bucket buffer's copy of the nodal values (BucketBuffer::ddmp) ----------------------

// Calls fn(buffer_values, block, node) for every node of the bucket's box (block −1: inactive).
template <class Fn>
void for_each_box_node(const Bucket& b, const BlockTable& table, BucketBuffer& buffer, Fn&& fn) {
  constexpr int w = BucketBuffer::width;
  if (buffer.ddmp.size() != size_t(w) * w * w * DdmpNodalValues::count)
    buffer.ddmp.assign(size_t(w) * w * w * DdmpNodalValues::count, Real(0));
  for (int i = b.box_lo[0]; i <= b.box_hi[0]; ++i)
    for (int j = b.box_lo[1]; j <= b.box_hi[1]; ++j)
      for (int k = b.box_lo[2]; k <= b.box_hi[2]; ++k) {
        const int block = table[size_t(occupancy_detail::table_index(b, i, j, k))];
        fn(buffer.ddmp.data() + buffer.ddmp_offset(i, j, k), block, occupancy_detail::local_bit(i, j, k));
      }
}

inline void clear_ddmp_box(const Bucket& b, const BlockTable& table, BucketBuffer& buffer) {
  for_each_box_node(b, table, buffer, [](Real* l, int, int) {
    for (int c = 0; c < DdmpNodalValues::count; ++c) l[c] = 0;
  });
}

// Adds the box's 6 mapped stress values into the nodal values.
inline void add_ddmp_box_to_grid(const Bucket& b, const BlockTable& table, BucketBuffer& buffer, DdmpNodalValues& nv) {
  for_each_box_node(b, table, buffer, [&](const Real* l, int block, int n) {
    if (block < 0) return;
    Real* g = nv.node(size_t(block), n);
    for (int c = 0; c < 6; ++c) g[c] += l[c];
  });
}

// The point's part of the nodal stress: −(1 − α) S̃_j V σ onto its cell's corners j
// (minus_volume = −V, σ in Voigt order).
inline void scatter_ddmp_corner_stress(const DdmpCornerStencil& st, Real minus_volume, const SymTensor& s,
                                       BucketBuffer& buffer) {
  for (int l = 0; l < 8; ++l) {
    const Real c = st.corner[l] * minus_volume;
    if (c == 0) continue;
    Real* node = buffer.ddmp_corner(st.base, l);
    for (int k = 0; k < 6; ++k) node[k] += c * s[k];
  }
}

// The point's smoothed part of L̄: (1 − α) Σ_j S̃_j L_j over its cell's corners, row-major.
inline void ddmp_corner_velocity_gradient(const DdmpCornerStencil& st, const BucketBuffer& buffer, Real L[9]) {
  for (int k = 0; k < 9; ++k) L[k] = 0;
  for (int l = 0; l < 8; ++l) {
    const Real* node = buffer.ddmp_corner(st.base, l);
    for (int k = 0; k < 9; ++k) L[k] += st.corner[l] * node[k];
  }
}

// Copies the nodal L_j of the box into the buffer.
inline void copy_ddmp_box_from_grid(const Bucket& b, const BlockTable& table, const DdmpNodalValues& nv,
                                    BucketBuffer& buffer) {
  for_each_box_node(b, table, buffer, [&](Real* l, int block, int n) {
    const Real* g = block < 0 ? nullptr : nv.node(size_t(block), n);
    for (int c = 0; c < DdmpNodalValues::count; ++c) l[c] = g ? g[c] : Real(0);
  });
}

}  // namespace latmpm::mpm
