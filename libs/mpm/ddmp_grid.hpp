// DDMP's smoothed gradient evaluated on the grid (Paper A Eq. 4, the paper's own practice).
//
// The per-particle sum over 4×4×4 nodes of Eq. 7 is split into a particle part on the
// particle's 8 cell corners and a constant 27-node stencil pass over the grid:
//   force:  −Σ_p V_p σ_p (1 − α_p) Σ_j S_j(x_p)/V_j ∫ S_j ∇S_i dV = −Σ_j σ^d_j ∫ S_j ∇S_i dV,
//           σ^d_j V_j = Σ_p (1 − α_p) S_j(x_p) V_p σ_p          (P2G, 6 values per node);
//   L:      Σ_i v_i ⊗ (1 − α_p) Σ_j S_j/V_j ∫ S_j ∇S_i = (1 − α_p) Σ_j S_j(x_p) L_j,
//           L_j = (1/V_j) Σ_i v_i ⊗ ∫ S_j ∇S_i dV                (grid pass, 9 values per node),
// with V_j = h³ and ∫ S_j ∇S_i dV = h² G(i − j), G the separable stencil of shape_ddmp.hpp
// (ddmp_smoothing_mass, ddmp_smoothing_slope). Both are the per-particle ∇̄S regrouped, so
// results agree with DdmpShape to round-off. The passes write each node from its 27
// neighbours in a fixed order: deterministic for any thread count.
//
// Small-mass nodes: ddmp_small_mass.hpp. The nodal values live beside the grid's 8 lanes,
// in DdmpNodalValues.
#pragma once
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "mpm/bucket_buffer.hpp"
#include "mpm/shape_ddmp.hpp"
#include "mpm/sparse_grid.hpp"

namespace latmpm::mpm {

// Per grid node, in block order like the grid (block · 64 + node):
//   after P2G: M_j = Σ_p (1 − α_p) S_j(x_p) (−V_p σ_p), Voigt order xx yy zz yz xz xy;
//   while small-mass nodes are handed on: the lanes being moved or read back;
//   before G2P: L_j, row-major (9 values).
// `coefficients`: 4 per node, (c₀, c) of the distribution coefficients of a small-mass node
// that hands on its lanes (find_ddmp_small_mass_nodes), zero for the others.
struct DdmpNodalValues {
  static constexpr int count = BucketBuffer::ddmp_values;
  std::vector<Real> values;
  std::vector<Real> coefficients;
  std::vector<uint8_t> block_has_small;  // per block: some node hands on
  std::vector<std::array<int, 27>> neighbours;  // per block: block (dx, dy, dz) ∈ {−1, 0, 1}³ away, −1 inactive
  std::vector<Real> alpha;  // α per point at x^n (DdmpAlphaCache), valid once alpha_filled
  bool alpha_filled = false;

  Real* node(size_t block, int n) { return values.data() + (block * SparseGrid::nodes_per_block + size_t(n)) * count; }
  const Real* node(size_t block, int n) const {
    return values.data() + (block * SparseGrid::nodes_per_block + size_t(n)) * count;
  }
};

namespace ddmp_grid_detail {
constexpr int bw = SparseGrid::block_width;
inline int neighbour_index(int dx, int dy, int dz) { return (dx + 1) * 9 + (dy + 1) * 3 + (dz + 1); }

// Position of node (i, j, k) (grid coordinates) in its block, and the block's place in a
// bucket's table of 4×4×4 blocks.
inline int local_index(int i, int j, int k) {
  return ((i - bw * floor_div(i, bw)) * bw + (j - bw * floor_div(j, bw))) * bw + (k - bw * floor_div(k, bw));
}
inline int table_index(const Bucket& b, int i, int j, int k) {
  return ((floor_div(i, bw) - first_table_block(b.coord[0])) * 4 + (floor_div(j, bw) - first_table_block(b.coord[1]))) * 4 +
         (floor_div(k, bw) - first_table_block(b.coord[2]));
}

// `Components` values of the nodes at local coordinates −Reach … bw − 1 + Reach around a
// block (index local + Reach): value c of node n of block b is get(b, n)[c]; zero in
// inactive blocks. The smoothing passes read one node around (Reach 1), the small-mass
// passes two (ddmp_grid_detail::reach).
template <int Reach, int Components>
struct BlockHalo {
  static constexpr int width = bw + 2 * Reach;
  Real v[width][width][width][Components];
  const Real* at(int li, int lj, int lk) const { return v[li + Reach][lj + Reach][lk + Reach]; }
};
template <int Components>
using NodeHalo = BlockHalo<1, Components>;

// Per axis, the halo splits into three segments: `Reach` nodes of the block below, the
// block's own `bw`, `Reach` of the block above; the halo is visited segment box by segment
// box (27 boxes, runs along k), with no per-node block lookup: fn(halo node, neighbour
// block or −1, node in it).
template <int Reach, class Fn>
void for_each_halo_node(const DdmpNodalValues& nv, size_t block, Fn&& fn) {
  static_assert(Reach <= bw, "a halo reaches at most one block away");
  constexpr int first[3] = {bw - Reach, 0, 0};  // first local index in the neighbour, per segment
  constexpr int count[3] = {Reach, bw, Reach};
  constexpr int start[3] = {0, Reach, Reach + bw};  // first halo index, per segment
  for (int di = -1; di <= 1; ++di)
    for (int dj = -1; dj <= 1; ++dj)
      for (int dk = -1; dk <= 1; ++dk) {
        const int nb = nv.neighbours[block][size_t(neighbour_index(di, dj, dk))];
        const int si = di + 1, sj = dj + 1, sk = dk + 1;
        for (int i = 0; i < count[si]; ++i)
          for (int j = 0; j < count[sj]; ++j)
            for (int k = 0; k < count[sk]; ++k)
              fn(start[si] + i, start[sj] + j, start[sk] + k, nb, ((first[si] + i) * bw + (first[sj] + j)) * bw + (first[sk] + k));
      }
}

// Copies the halo's values: value c of node n of block b is get(b, n)[c]; zero in inactive blocks.
template <int Reach, int Components, class Get>
void load_halo(const DdmpNodalValues& nv, size_t block, Get get, BlockHalo<Reach, Components>& halo) {
  for_each_halo_node<Reach>(nv, block, [&](int hi, int hj, int hk, int nb, int n) {
    Real* out = halo.v[hi][hj][hk];
    if (nb < 0) {
      for (int c = 0; c < Components; ++c) out[c] = 0;
      return;
    }
    const Real* in = get(size_t(nb), n);
    for (int c = 0; c < Components; ++c) out[c] = in[c];
  });
}

// The halo's nodes as indices block · 64 + node into the grid's and DdmpNodalValues' node
// order, −1 in inactive blocks: for passes that read a few of the halo's nodes (the
// small-mass passes), cheaper than copying every node's values.
template <int Reach>
struct IndexHalo {
  static constexpr int width = bw + 2 * Reach;
  int32_t v[width][width][width];
  int32_t at(int li, int lj, int lk) const { return v[li + Reach][lj + Reach][lk + Reach]; }
};
template <int Reach>
void load_index_halo(const DdmpNodalValues& nv, size_t block, IndexHalo<Reach>& halo) {
  for_each_halo_node<Reach>(nv, block, [&](int hi, int hj, int hk, int nb, int n) {
    halo.v[hi][hj][hk] = nb < 0 ? -1 : int32_t(nb * SparseGrid::nodes_per_block + n);
  });
}

// G(o) of the smoothing integral ∫ S_j ∇S_i dV = h² G(i − j) for the 27 offsets
// o ∈ {−1, 0, 1}³ (index neighbour_index).
struct SmoothingStencil {
  std::array<Vec3, 27> G;
};
inline const SmoothingStencil& smoothing_stencil() {
  static const SmoothingStencil s = [] {
    SmoothingStencil t;
    for (int x = -1; x <= 1; ++x)
      for (int y = -1; y <= 1; ++y)
        for (int z = -1; z <= 1; ++z) {
          const Real mx = ddmp_smoothing_mass(x), my = ddmp_smoothing_mass(y), mz = ddmp_smoothing_mass(z);
          t.G[size_t(neighbour_index(x, y, z))] =
              Vec3(ddmp_smoothing_slope(x) * my * mz, mx * ddmp_smoothing_slope(y) * mz, mx * my * ddmp_smoothing_slope(z));
        }
    return t;
  }();
  return s;
}

}  // namespace ddmp_grid_detail

// Sizes and zeroes the nodal values for the grid's active blocks and finds each block's
// neighbours.
inline void prepare_ddmp_nodal_values(const SparseGrid& grid, DdmpNodalValues& nv) {
  using namespace ddmp_grid_detail;
  const size_t blocks = grid.block_count();
  nv.values.assign(blocks * SparseGrid::nodes_per_block * DdmpNodalValues::count, Real(0));
  nv.coefficients.assign(blocks * SparseGrid::nodes_per_block * 4, Real(0));
  nv.block_has_small.assign(blocks, 0);
  nv.neighbours.resize(blocks);
  nv.alpha_filled = false;  // a new step: the points have moved
  tbb::parallel_for(size_t(0), blocks, [&](size_t b) {
    const auto c = grid.coord(b);
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz)
          nv.neighbours[b][size_t(neighbour_index(dx, dy, dz))] = grid.find(c[0] + dx, c[1] + dy, c[2] + dz);
  });
}

// The α cache of a particle pass: the first pass of a step (after prepare_ddmp_nodal_values)
// fills it; end_ddmp_alpha_pass after a pass that visited every point makes it valid.
inline DdmpAlphaCache begin_ddmp_alpha_pass(DdmpNodalValues& nv, size_t particles) {
  if (!nv.alpha_filled) nv.alpha.resize(particles);
  return {nv.alpha.data(), !nv.alpha_filled};
}
inline void end_ddmp_alpha_pass(DdmpNodalValues& nv) { nv.alpha_filled = true; }

// Zeroes every node's values (before a scatter that maps the stress again).
inline void clear_ddmp_nodal_values(DdmpNodalValues& nv) { std::fill(nv.values.begin(), nv.values.end(), Real(0)); }

// f_i += Σ_j (M_j / h³) h² G(i − j) = Σ_j M_j G(i − j) / h over the 27 neighbours j, with
// M_j the mapped −(1 − α) S V σ (Voigt order): the smoothed part of Eq. 6's force, into
// the grid's force lanes.
inline void add_ddmp_smoothed_force(SparseGrid& grid, const DdmpNodalValues& nv, Real h) {
  using namespace ddmp_grid_detail;
  const auto& G = smoothing_stencil().G;
  const Real inv_h = 1 / h;
  tbb::parallel_for(size_t(0), grid.block_count(), [&](size_t b) {
    NodeHalo<6> s;
    load_halo<1, 6>(nv, b, [&](size_t nb, int n) { return nv.node(nb, n); }, s);
    for (int i = 0; i < bw; ++i)
      for (int j = 0; j < bw; ++j)
        for (int k = 0; k < bw; ++k) {
          Real f[3] = {0, 0, 0};
          for (int x = -1; x <= 1; ++x)
            for (int y = -1; y <= 1; ++y)
              for (int z = -1; z <= 1; ++z) {
                const Real* sj = s.v[i + 1 - x][j + 1 - y][k + 1 - z];  // node j = i − o
                const Vec3& g = G[size_t(neighbour_index(x, y, z))];
                f[0] += sj[0] * g[0] + sj[5] * g[1] + sj[4] * g[2];
                f[1] += sj[5] * g[0] + sj[1] * g[1] + sj[3] * g[2];
                f[2] += sj[4] * g[0] + sj[3] * g[1] + sj[2] * g[2];
              }
          Real* node = grid.block(b) + SparseGrid::node_offset(i, j, k);
          for (int a = 0; a < 3; ++a) node[lane::force + a] += inv_h * f[a];
        }
  });
}

// L_j = (1/h³) Σ_i v_i ⊗ h² G(i − j) from the grid velocities in lanes velocity_lane … + 2,
// into the nodal values (row-major).
inline void ddmp_nodal_velocity_gradient(const SparseGrid& grid, int velocity_lane, Real h, DdmpNodalValues& nv) {
  using namespace ddmp_grid_detail;
  const auto& G = smoothing_stencil().G;
  const Real inv_h = 1 / h;
  tbb::parallel_for(size_t(0), grid.block_count(), [&](size_t b) {
    NodeHalo<3> v;
    load_halo<1, 3>(nv, b, [&](size_t nb, int n) { return grid.block(nb) + n * lane::count + velocity_lane; }, v);
    for (int i = 0; i < bw; ++i)
      for (int j = 0; j < bw; ++j)
        for (int k = 0; k < bw; ++k) {
          Real L[9] = {};
          for (int x = -1; x <= 1; ++x)
            for (int y = -1; y <= 1; ++y)
              for (int z = -1; z <= 1; ++z) {
                const Real* vi = v.v[i + 1 + x][j + 1 + y][k + 1 + z];  // node i = j + o
                const Vec3& g = G[size_t(neighbour_index(x, y, z))];
                for (int r = 0; r < 3; ++r)
                  for (int c = 0; c < 3; ++c) L[r * 3 + c] += vi[r] * g[c];
              }
          Real* out = nv.node(b, (i * bw + j) * bw + k);
          for (int c = 0; c < 9; ++c) out[c] = inv_h * L[c];
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
        const int block = table[size_t(ddmp_grid_detail::table_index(b, i, j, k))];
        fn(buffer.ddmp.data() + buffer.ddmp_offset(i, j, k), block, ddmp_grid_detail::local_index(i, j, k));
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

// The point's part of the nodal stress: −(1 − α) S_j V σ onto its cell's corners j
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

// The point's smoothed part of L̄: (1 − α) Σ_j S_j L_j over its cell's corners, row-major.
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
