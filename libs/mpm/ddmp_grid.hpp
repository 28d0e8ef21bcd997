// DDMP's smoothed gradient evaluated on the grid (Paper A Eq. 4, the paper's own practice).
//
// The per-particle sum over 4×4×4 nodes of Eq. 7 is split into a particle part on the
// particle's 8 cell corners and a constant 27-node stencil pass over the grid (separable:
// three 1D passes of 3 taps):
//   force:  −Σ_p V_p σ_p (1 − α_p) Σ_j S_j(x_p)/V_j ∫ S_j ∇S_i dV = −Σ_j σ^d_j ∫ S_j ∇S_i dV,
//           σ^d_j V_j = Σ_p (1 − α_p) S_j(x_p) V_p σ_p          (P2G, 6 values per node);
//   L:      Σ_i v_i ⊗ (1 − α_p) Σ_j S_j/V_j ∫ S_j ∇S_i = (1 − α_p) Σ_j S_j(x_p) L_j,
//           L_j = (1/V_j) Σ_i v_i ⊗ ∫ S_j ∇S_i dV                (grid pass, 9 values per node),
// with V_j = h³ and ∫ S_j ∇S_i dV = h² G(i − j), G the separable stencil of shape_ddmp.hpp
// (ddmp_smoothing_mass, ddmp_smoothing_slope). Both are the per-particle ∇̄S regrouped, so
// results agree with DdmpShape to round-off. The passes write each node from its
// neighbours in a fixed order: deterministic for any thread count.
//
// Small-mass nodes: ddmp_small_mass.hpp. The nodal values live beside the grid's 8 lanes,
// in DdmpNodalValues.
#pragma once
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "mpm/bucket_buffer.hpp"
#include "mpm/shape_ddmp.hpp"
#include "mpm/simd.hpp"
#include "mpm/sparse_grid.hpp"

namespace latmpm::mpm {

struct DdmpDistribution;

// Per block, `count` values a node (block · 64 · count):
//   after P2G: M_j = Σ_p (1 − α_p) S_j(x_p) (−V_p σ_p), Voigt order xx yy zz yz xz xy, one
//     component at a time: component c of node n at c · 64 + n (stress_component), so that
//     the smoothing pass's halo copies rows of four nodes as they lie;
//   before G2P: L_j, node by node, row-major (9 values a node: node(b, n)).
// Small-mass nodes (find_ddmp_small_mass_nodes): per block a 64-bit mask of the nodes that
// hand on their lanes (bit n = node n), and per such node its distribution.
struct DdmpNodalValues {
  static constexpr int count = BucketBuffer::ddmp_values;
  static constexpr int stress_components = 6;  // of M (Voigt)
  NodeStorage values;  // block by block, on large pages like the grid's lanes
  std::vector<const DdmpDistribution*> distributions;  // per node handing on: its shares (ddmp_small_mass.hpp)
  uint64_t distribution_generation = 0;                // of the memo the distributions point into
  std::vector<uint64_t> handing;                       // per block: the nodes that hand on
  std::vector<uint64_t> sizeable_mask, mass_mask;      // per block: nodes with mass ≥ the small mass, > 0
  // What the last find_ddmp_small_mass_nodes saw and decided: a block whose 27 blocks around
  // kept their masks keeps its nodes' patterns, hence whether they hand on and their
  // distributions, and is not looked at again (most blocks, most steps).
  struct LastFind {
    uint64_t layout = 0, generation = 0;        // of the grid's blocks and of the memo; 0: nothing to reuse
    Real small_mass = 0;                        // the threshold it used
    std::vector<uint64_t> candidates, handing;  // per block: the nodes that may hand on, and those that do
    std::vector<uint64_t> changed;              // per block, this step: its nodes whose masks are not the last find's
  } last_find;
  // mass_mask is this step's: find_ddmp_small_mass_nodes ran after the step's grid was
  // prepared (the mass mapped by its scatter, before any node handed its mass on).
  bool mass_mask_current = false;
  // The blocks with nodes handing on, for the hand-on's order (move_ddmp_small_mass_lanes):
  // per tile colour (parity of the 3×3×3-block tile's coordinates) its tiles, each a run of
  // `handing_blocks` from handing_tile_begin[t] to [t + 1], in block-colour order (mod 3).
  std::array<std::vector<uint32_t>, 8> handing_blocks, handing_tile_begin;
  std::vector<std::array<int, 27>> neighbours;  // per block: block (dx, dy, dz) ∈ {−1, 0, 1}³ away, −1 inactive
  uint64_t neighbours_layout = 0;               // the grid's layout() they were found for
  std::vector<Real> alpha;  // α per point at x^n (DdmpAlphaCache, fill_ddmp_alpha)

  // Whether the L pass left block b out (no node with mass this step: ddmp_nodal_velocity_gradient);
  // its L is then 0, which copy_ddmp_box_from_grid supplies.
  bool gradient_left_out(size_t b) const { return mass_mask_current && mass_mask[b] == 0; }

  // M's component c of the block's 64 nodes (after P2G).
  Real* stress_component(size_t block, int c) {
    return values.data() + (block * count + size_t(c)) * SparseGrid::nodes_per_block;
  }
  const Real* stress_component(size_t block, int c) const {
    return values.data() + (block * count + size_t(c)) * SparseGrid::nodes_per_block;
  }
  // L_j of node n (before G2P).
  Real* node(size_t block, int n) { return values.data() + (block * SparseGrid::nodes_per_block + size_t(n)) * count; }
  const Real* node(size_t block, int n) const {
    return values.data() + (block * SparseGrid::nodes_per_block + size_t(n)) * count;
  }
};

namespace ddmp_grid_detail {
constexpr int bw = SparseGrid::block_width;
inline int neighbour_index(int dx, int dy, int dz) { return (dx + 1) * 9 + (dy + 1) * 3 + (dz + 1); }

// `Components` values of the nodes at local coordinates −Reach … bw − 1 + Reach around a
// block, component by component: value c of halo node (i, j, k) (local + Reach) at
// v[c][i][j][k], so that the smoothing passes run along whole rows of one component (a row
// of a block is 4 nodes: one vector of 4 doubles). The smoothing passes read one node around
// (Reach 1).
template <int Reach, int Components>
struct BlockHalo {
  static constexpr int width = bw + 2 * Reach;
  alignas(64) Real v[Components][width][width][width];
};
template <int Components>
using NodeHalo = BlockHalo<1, Components>;

// box(si, sj, sk) for the 27 segment boxes of a halo (below, own, above per axis: 0, 1, 2),
// each index a compile-time constant.
template <class Box, int... S>
[[gnu::always_inline]] inline void for_each_halo_box(Box& box, std::integer_sequence<int, S...>) {
  (box(std::integral_constant<int, S / 9>{}, std::integral_constant<int, (S / 3) % 3>{},
       std::integral_constant<int, S % 3>{}),
   ...);
}

// The columns of a 4×4 block given by its rows: column[q][r] = row r's value q.
[[gnu::always_inline]] inline void transpose_rows(Axes r0, Axes r1, Axes r2, Axes r3, Axes column[4]) {
  const Axes even01 = __builtin_shufflevector(r0, r1, 0, 4, 2, 6), odd01 = __builtin_shufflevector(r0, r1, 1, 5, 3, 7);
  const Axes even23 = __builtin_shufflevector(r2, r3, 0, 4, 2, 6), odd23 = __builtin_shufflevector(r2, r3, 1, 5, 3, 7);
  column[0] = __builtin_shufflevector(even01, even23, 0, 1, 4, 5);
  column[1] = __builtin_shufflevector(odd01, odd23, 0, 1, 4, 5);
  column[2] = __builtin_shufflevector(even01, even23, 2, 3, 6, 7);
  column[3] = __builtin_shufflevector(odd01, odd23, 2, 3, 6, 7);
}

// Copies the halo's values: value c of node n of block nb is
// first_value(nb)[n · Stride + c · ComponentStride] — node by node (Stride ≥ Components,
// ComponentStride 1: the grid's lanes) or component by component (Stride 1,
// ComponentStride 64: DDMP's M); zero in inactive blocks. Per axis the halo splits into
// three segments — `Reach` nodes of the block below, the block's own `bw`, `Reach` of the
// block above — so it is 27 boxes, each from one block; every box's loops have fixed counts
// (a template per box), and the block's own 64 nodes are one of them. Where a box's rows
// along k are whole (its k segment is the block's own), a row is read four nodes at a time:
// component by component one vector a component; node by node four values of each node at a
// time, transposed (the last group may read past `Components`, within the node's `Stride`).
template <int Reach, int Components, int Stride, int ComponentStride, class FirstValue>
void load_halo(const DdmpNodalValues& nv, size_t block, FirstValue first_value, BlockHalo<Reach, Components>& halo) {
  static_assert(Reach <= bw, "a halo reaches at most one block away");
  constexpr bool by_component = Stride == 1;
  static_assert(by_component ? ComponentStride >= SparseGrid::nodes_per_block
                             : ComponentStride == 1 && (Components + 3) / 4 * 4 <= Stride,
                "component by component, or a node's last group of four values within its stride");
  const auto box = [&](auto si, auto sj, auto sk) __attribute__((always_inline)) {
    // Per segment s (0 below, 1 own, 2 above): first local index in the block, count, first halo index.
    constexpr int first[3] = {bw - Reach, 0, 0}, count[3] = {Reach, bw, Reach}, start[3] = {0, Reach, Reach + bw};
    constexpr int I = decltype(si)::value, J = decltype(sj)::value, K = decltype(sk)::value;
    const int nb = nv.neighbours[block][size_t(neighbour_index(I - 1, J - 1, K - 1))];
    // The test once per box, not per value (the loops then have no branch).
    if (nb < 0) {
      for (int c = 0; c < Components; ++c)
        for (int i = 0; i < count[I]; ++i)
          for (int j = 0; j < count[J]; ++j)
            for (int k = 0; k < count[K]; ++k) halo.v[c][start[I] + i][start[J] + j][start[K] + k] = 0;
      return;
    }
    const Real* in = first_value(size_t(nb));
    if constexpr (K == 1 && by_component) {
      for (int c = 0; c < Components; ++c)
        for (int i = 0; i < count[I]; ++i)
          for (int j = 0; j < count[J]; ++j)
            num::store(&halo.v[c][start[I] + i][start[J] + j][start[K]],
                       num::load<Axes>(in + c * ComponentStride + ((first[I] + i) * bw + (first[J] + j)) * bw));
    } else if constexpr (K == 1) {
      // A whole row along k (4 nodes) at a time: its nodes' values four components at a time,
      // turned into four component rows (transpose_rows). These boxes hold two thirds of the
      // halo, and copied one value at a time they cost more than the smoothing passes
      // themselves (perf, T2P20-E8, 2026-11-28); what is left waits mostly on the first loads
      // of the neighbouring blocks.
      for (int i = 0; i < count[I]; ++i)
        for (int j = 0; j < count[J]; ++j) {
          const Real* row = in + ((first[I] + i) * bw + (first[J] + j)) * bw * Stride;
          for (int c0 = 0; c0 < Components; c0 += 4) {
            Axes column[4];
            transpose_rows(num::load<Axes>(row + c0), num::load<Axes>(row + Stride + c0),
                           num::load<Axes>(row + 2 * Stride + c0), num::load<Axes>(row + 3 * Stride + c0), column);
            for (int q = 0; q < 4 && c0 + q < Components; ++q)
              num::store(&halo.v[c0 + q][start[I] + i][start[J] + j][start[K]], column[q]);
          }
        }
    } else {
      for (int c = 0; c < Components; ++c)
        for (int i = 0; i < count[I]; ++i)
          for (int j = 0; j < count[J]; ++j)
            for (int k = 0; k < count[K]; ++k)
              halo.v[c][start[I] + i][start[J] + j][start[K] + k] =
                  in[(((first[I] + i) * bw + (first[J] + j)) * bw + (first[K] + k)) * Stride + c * ComponentStride];
    }
  };
  for_each_halo_box(box, std::make_integer_sequence<int, 27>{});
}

// The smoothing integral's 1D factors (shape_ddmp.hpp) as operators along one axis of a
// halo, the stencil's three taps at nodes n − 1, n, n + 1 (u₋, u₀, u₊):
//   mass M:   Σ_o M(o) u(n − o) = (u₋ + 4 u₀ + u₊)/6 (symmetric);
//   slope D:  Σ_o D(o) u(n − o) = ½ (u₋ − u₊)  (the force: node j = i − o feeds node i);
//   slope D': Σ_o D(o) u(n + o) = ½ (u₊ − u₋)  (L: node i = j + o feeds node j).
// G = (D M M, M D M, M M D) is separable, so the 27-node sums of the force and of L are
// three passes of 3 taps (z, then y, then x) instead of one of 27.
inline Real smooth_mass(Real below, Real at, Real above) {
  return ddmp_smoothing_mass(1) * below + ddmp_smoothing_mass(0) * at + ddmp_smoothing_mass(-1) * above;
}
inline Real smooth_slope(Real below, Real above) {
  return ddmp_smoothing_slope(1) * below + ddmp_smoothing_slope(-1) * above;
}

// One component of a box, and the same box with one more node on each side along `Axis`:
// the input of a pass along that axis.
template <int NA, int NB, int NC>
using Plane = Real[NA][NB][NC];
template <int Axis, int NA, int NB, int NC>
using PassInput = Real[NA + 2 * (Axis == 0)][NB + 2 * (Axis == 1)][NC + 2 * (Axis == 2)];

// out[a][b][c] = op(u₋, u₀, u₊), the three taps of node (a, b, c) along `Axis` (input index
// +0, +1, +2 along it). Rows along c are contiguous in both: the compiler makes each row one
// vector operation.
template <int Axis, int NA, int NB, int NC, class Op>
[[gnu::always_inline]] inline void pass_along(const PassInput<Axis, NA, NB, NC>& in, Plane<NA, NB, NC>& out, Op op) {
  constexpr int da = Axis == 0, db = Axis == 1, dc = Axis == 2;
  for (int a = 0; a < NA; ++a)
    for (int b = 0; b < NB; ++b)
      for (int c = 0; c < NC; ++c)
        out[a][b][c] = op(in[a][b][c], in[a + da][b + db][c + dc], in[a + 2 * da][b + 2 * db][c + 2 * dc]);
}
// The three operators of the header comment on one component.
template <int Axis, int NA, int NB, int NC>
[[gnu::always_inline]] inline void mass_along(const PassInput<Axis, NA, NB, NC>& in, Plane<NA, NB, NC>& out) {
  pass_along<Axis, NA, NB, NC>(in, out, [](Real below, Real at, Real above) { return smooth_mass(below, at, above); });
}
template <int Axis, int NA, int NB, int NC>
[[gnu::always_inline]] inline void slope_along(const PassInput<Axis, NA, NB, NC>& in, Plane<NA, NB, NC>& out) {
  pass_along<Axis, NA, NB, NC>(in, out, [](Real below, Real, Real above) { return smooth_slope(below, above); });
}
template <int Axis, int NA, int NB, int NC>
[[gnu::always_inline]] inline void reverse_slope_along(const PassInput<Axis, NA, NB, NC>& in, Plane<NA, NB, NC>& out) {
  pass_along<Axis, NA, NB, NC>(in, out, [](Real below, Real, Real above) { return smooth_slope(above, below); });
}
}  // namespace ddmp_grid_detail

// Sizes the nodal values for the grid's active blocks (not zeroed: see below) and finds each
// block's neighbours (again only when the set of blocks changed: 27 look-ups a block each
// step were 1 % of a paper-size DDMP step).
inline void prepare_ddmp_nodal_values(const SparseGrid& grid, DdmpNodalValues& nv) {
  using namespace ddmp_grid_detail;
  const size_t blocks = grid.block_count();
  // Every pass writes the values before it reads them (the stress scatter clears them);
  // distributions are read only where `handing` says so.
  nv.values.resize(blocks * SparseGrid::nodes_per_block * DdmpNodalValues::count);
  nv.distributions.resize(blocks * SparseGrid::nodes_per_block);
  nv.handing.assign(blocks, 0);  // until find_ddmp_small_mass_nodes, nothing hands on
  nv.mass_mask_current = false;
  if (nv.neighbours_layout == grid.layout()) return;
  for (auto& list : nv.handing_blocks) list.clear();  // of other blocks: find_ddmp_small_mass_nodes remakes them
  for (auto& list : nv.handing_tile_begin) list.clear();
  nv.neighbours.resize(blocks);
  nv.neighbours_layout = grid.layout();
  tbb::parallel_for(size_t(0), blocks, [&](size_t b) {
    const auto c = grid.coord(b);
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz)
          nv.neighbours[b][size_t(neighbour_index(dx, dy, dz))] = grid.find(c[0] + dx, c[1] + dy, c[2] + dz);
  });
}

// α of every point at x^n, once per step (before the step's first pass; DdmpAlphaCache).
inline void fill_ddmp_alpha(const std::vector<Vec3>& positions, Real h, const DdmpPartition& partition,
                            DdmpNodalValues& nv) {
  nv.alpha.resize(positions.size());
  constexpr size_t chunk = 4096;
  tbb::parallel_for(size_t(0), (positions.size() + chunk - 1) / chunk, [&](size_t c) {
    const size_t first = c * chunk, n = std::min(chunk, positions.size() - first);
    ddmp_partition_of_points(positions.data() + first, n, 1 / h, partition, nv.alpha.data() + first);
  });
}
inline DdmpAlphaCache ddmp_alpha_of_step(DdmpNodalValues& nv) { return {nv.alpha.data()}; }

// Zeroes every node's M (before a scatter that maps the stress again), block by block in
// parallel. L is not cleared: the L pass writes it wherever it is read
// (copy_ddmp_box_from_grid supplies the zeros of the blocks it leaves out).
inline void clear_ddmp_nodal_values(DdmpNodalValues& nv) {
  const size_t blocks = nv.values.size() / (size_t(SparseGrid::nodes_per_block) * DdmpNodalValues::count);
  tbb::parallel_for(size_t(0), blocks, [&](size_t b) {
    Real* m = nv.stress_component(b, 0);
    std::fill(m, m + DdmpNodalValues::stress_components * SparseGrid::nodes_per_block, Real(0));
  });
}

// f_i += Σ_j (M_j / h³) h² G(i − j) = Σ_j M_j G(i − j) / h over the 27 neighbours j, with
// M_j the mapped −(1 − α) S V σ (Voigt order xx yy zz yz xz xy): the smoothed part of Eq.
// 6's force, into the grid's force lanes. Separable: z, y, x passes of 3 taps, e.g.
// f_x = D_x M_y M_z σxx + M_x D_y M_z σxy + M_x M_y D_z σxz.
inline void add_ddmp_smoothed_force(SparseGrid& grid, const DdmpNodalValues& nv, Real h) {
  using namespace ddmp_grid_detail;
  const Real inv_h = 1 / h;
  tbb::parallel_for(size_t(0), grid.block_count(), [&](size_t b) {
    constexpr int components = DdmpNodalValues::stress_components;
    NodeHalo<components> s;
    load_halo<1, components, 1, SparseGrid::nodes_per_block>(nv, b, [&](size_t nb) { return nv.stress_component(nb, 0); },
                                                             s);
    constexpr int w = bw + 2;
    // z: M_z of the 6 components, D_z of σxz, σyz, σzz (Voigt xx yy zz yz xz xy: 0 1 2 3 4 5).
    alignas(64) Real z[9][w][w][bw];
    for (int q = 0; q < components; ++q) mass_along<2, w, w, bw>(s.v[q], z[q]);
    slope_along<2, w, w, bw>(s.v[4], z[6]);
    slope_along<2, w, w, bw>(s.v[3], z[7]);
    slope_along<2, w, w, bw>(s.v[2], z[8]);
    // y: M_y M_z (xx, xy, xz), D_y M_z (xy, yy, yz), M_y D_z (xz, yz, zz).
    alignas(64) Real y[9][w][bw][bw];
    mass_along<1, w, bw, bw>(z[0], y[0]);
    mass_along<1, w, bw, bw>(z[5], y[1]);
    mass_along<1, w, bw, bw>(z[4], y[2]);
    slope_along<1, w, bw, bw>(z[5], y[3]);
    slope_along<1, w, bw, bw>(z[1], y[4]);
    slope_along<1, w, bw, bw>(z[3], y[5]);
    for (int q = 6; q < 9; ++q) mass_along<1, w, bw, bw>(z[q], y[q]);
    // x: f_a = D_x (M_y M_z σ_xa) + M_x (D_y M_z σ_ya) + M_x (M_y D_z σ_za).
    alignas(64) Real f[3][bw][bw][bw];
    for (int a = 0; a < 3; ++a)
      for (int i = 0; i < bw; ++i)
        for (int j = 0; j < bw; ++j)
          for (int k = 0; k < bw; ++k)
            f[a][i][j][k] = smooth_slope(y[a][i][j][k], y[a][i + 2][j][k]) +
                            smooth_mass(y[3 + a][i][j][k], y[3 + a][i + 1][j][k], y[3 + a][i + 2][j][k]) +
                            smooth_mass(y[6 + a][i][j][k], y[6 + a][i + 1][j][k], y[6 + a][i + 2][j][k]);
    for (int i = 0; i < bw; ++i)
      for (int j = 0; j < bw; ++j)
        for (int k = 0; k < bw; ++k) {
          Real* node = grid.block(b) + SparseGrid::node_offset(i, j, k);
          for (int a = 0; a < 3; ++a) node[lane::force + a] += inv_h * f[a][i][j][k];
        }
  });
}

// L_j = (1/h³) Σ_i v_i ⊗ h² G(i − j) from the grid velocities in lanes velocity_lane … + 2,
// into the nodal values (row-major): L_rc = D'_c-separable passes of v_r, as the force.
// Only a node with mass is a corner j of a point's cell with S_j > 0, so a block none of
// whose nodes had mass this step (the layer of blocks DDMP adds around the points, for the
// smoothed force) is left out: its L is 0, which copy_ddmp_box_from_grid supplies (the points
// read its nodes, if at all, with weight 0), so it is neither computed nor written.
inline void ddmp_nodal_velocity_gradient(const SparseGrid& grid, int velocity_lane, Real h, DdmpNodalValues& nv) {
  using namespace ddmp_grid_detail;
  const Real inv_h = 1 / h;
  tbb::parallel_for(size_t(0), grid.block_count(), [&](size_t b) {
    if (nv.gradient_left_out(b)) return;
    NodeHalo<3> v;
    load_halo<1, 3, lane::count, 1>(nv, b, [&](size_t nb) { return grid.block(nb) + velocity_lane; }, v);
    constexpr int w = bw + 2;
    // z: M_z v, D'_z v.
    alignas(64) Real z[6][w][w][bw];
    for (int r = 0; r < 3; ++r) {
      mass_along<2, w, w, bw>(v.v[r], z[r]);
      reverse_slope_along<2, w, w, bw>(v.v[r], z[3 + r]);
    }
    // y: M_y M_z v, D'_y M_z v, M_y D'_z v.
    alignas(64) Real y[9][w][bw][bw];
    for (int r = 0; r < 3; ++r) {
      mass_along<1, w, bw, bw>(z[r], y[r]);
      reverse_slope_along<1, w, bw, bw>(z[r], y[3 + r]);
      mass_along<1, w, bw, bw>(z[3 + r], y[6 + r]);
    }
    // x: L_r0 = D'_x M_y M_z v_r, L_r1 = M_x D'_y M_z v_r, L_r2 = M_x M_y D'_z v_r.
    alignas(64) Real L[9][bw][bw][bw];
    for (int r = 0; r < 3; ++r) {
      reverse_slope_along<0, bw, bw, bw>(y[r], L[r * 3 + 0]);
      mass_along<0, bw, bw, bw>(y[3 + r], L[r * 3 + 1]);
      mass_along<0, bw, bw, bw>(y[6 + r], L[r * 3 + 2]);
    }
    for (int i = 0; i < bw; ++i)
      for (int j = 0; j < bw; ++j)
        for (int k = 0; k < bw; ++k) {
          Real* out = nv.node(b, (i * bw + j) * bw + k);
          for (int c = 0; c < 9; ++c) out[c] = inv_h * L[c][i][j][k];
        }
  });
}

// --- The bucket buffer's copy of the nodal values (BucketBuffer::ddmp) ----------------------

// Calls fn(buffer_values, block, node, count) for every run of nodes of the bucket's columns
// (for_each_column_run; block −1: inactive): the runs are contiguous in the nodal values and
// in the buffer's `ddmp`, ddmp_values a node. DDMP's points reach only their cell's corners,
// which the columns of DdmpGridShape's reach hold; the rest of the buffer is neither
// written by the scatter nor read by the gather. (Node by node over the whole box, with a
// block look-up per node, these passes took 7 % of a paper-size DDMP step: 2026-11-28.)
template <class Fn>
void for_each_ddmp_box_run(const Bucket& b, const BucketColumns& columns, const BlockTable& table, BucketBuffer& buffer,
                           Fn&& fn) {
  constexpr int w = BucketBuffer::width;
  if (buffer.ddmp.size() != size_t(w) * w * w * DdmpNodalValues::count)
    buffer.ddmp.assign(size_t(w) * w * w * DdmpNodalValues::count, Real(0));
  for_each_column_run(b, columns, table, buffer, [&](int block, int node, int i, int j, int k, int count) {
    fn(buffer.ddmp.data() + buffer.ddmp_offset(i, j, k), block, node, count);
  });
}

inline void clear_ddmp_box(const Bucket& b, const BucketColumns& columns, const BlockTable& table, BucketBuffer& buffer) {
  for_each_ddmp_box_run(b, columns, table, buffer, [](Real* l, int, int, int count) {
    std::fill(l, l + count * DdmpNodalValues::count, Real(0));
  });
}

// Adds the box's 6 mapped stress values (node by node in the buffer) into the nodal values
// (component by component).
inline void add_ddmp_box_to_grid(const Bucket& b, const BucketColumns& columns, const BlockTable& table,
                                 BucketBuffer& buffer, DdmpNodalValues& nv) {
  using ddmp_grid_detail::transpose_rows;
  constexpr int stride = DdmpNodalValues::count;
  for_each_ddmp_box_run(b, columns, table, buffer, [&](const Real* l, int block, int node, int count) {
    if (block < 0) return;
    if (count == 4) {
      // A whole column of the block: four nodes' components 0–3 and 4–7 as vectors, turned
      // into component rows (the last two of the second group are not M's and are dropped).
      // Each value gets the same single addition as below.
      Axes low[4], high[4];
      transpose_rows(num::load<Axes>(l), num::load<Axes>(l + stride), num::load<Axes>(l + 2 * stride),
                     num::load<Axes>(l + 3 * stride), low);
      transpose_rows(num::load<Axes>(l + 4), num::load<Axes>(l + stride + 4), num::load<Axes>(l + 2 * stride + 4),
                     num::load<Axes>(l + 3 * stride + 4), high);
      for (int c = 0; c < DdmpNodalValues::stress_components; ++c) {
        Real* g = nv.stress_component(size_t(block), c) + node;
        num::store(g, num::load<Axes>(g) + (c < 4 ? low[c] : high[c - 4]));
      }
      return;
    }
    for (int c = 0; c < DdmpNodalValues::stress_components; ++c) {
      Real* g = nv.stress_component(size_t(block), c) + node;
      for (int n = 0; n < count; ++n) g[n] += l[n * stride + c];
    }
  });
}

// The point's part of the nodal stress: −(1 − α) S_j V σ onto its cell's corners j
// (minus_volume = −V, σ in Voigt order). Per corner one 4-lane and one 2-lane multiply-add,
// each lane the scalar loop's fused c·σ_k + node_k (the same bits); the corners unrolled,
// so their offsets are constants.
inline void scatter_ddmp_corner_stress(const DdmpCornerStencil& st, Real minus_volume, const SymTensor& s,
                                       BucketBuffer& buffer) {
  Real* cell = buffer.ddmp_cell(st.base);
  const Axes s_low = {s[0], s[1], s[2], s[3]};
  const Duo s_high = {s[4], s[5]};
#pragma GCC unroll 8
  for (int l = 0; l < 8; ++l) {
    const Real c = st.corner[l] * minus_volume;
    if (c == 0) continue;
    Real* node = cell + BucketBuffer::ddmp_corner_offset(l);
    num::store(node, num::load<Axes>(node) + c * s_low);
    num::store(node + 4, num::load<Duo>(node + 4) + c * s_high);
  }
}

// The point's smoothed part of L̄: (1 − α) Σ_j S_j L_j over its cell's corners, row-major.
// Components 0–3 and 4–7 as 4-lane vectors and 8 alone, summed corner by corner in the
// scalar loop's order.
inline void ddmp_corner_velocity_gradient(const DdmpCornerStencil& st, const BucketBuffer& buffer, Real L[9]) {
  const Real* cell = buffer.ddmp_cell(st.base);
  Axes low{}, high{};
  Real last = 0;
#pragma GCC unroll 8
  for (int l = 0; l < 8; ++l) {
    const Real* node = cell + BucketBuffer::ddmp_corner_offset(l);
    const Real c = st.corner[l];
    low += c * num::load<Axes>(node);
    high += c * num::load<Axes>(node + 4);
    last += c * node[8];
  }
  num::store(L, low);
  num::store(L + 4, high);
  L[8] = last;
}

// Copies the nodal L_j of the box's columns into the buffer: zero in inactive blocks and,
// when the mass mask is this step's, in blocks without mass, whose L the L pass does not
// write (no point has a corner there).
inline void copy_ddmp_box_from_grid(const Bucket& b, const BucketColumns& columns, const BlockTable& table,
                                    const DdmpNodalValues& nv, BucketBuffer& buffer) {
  for_each_ddmp_box_run(b, columns, table, buffer, [&](Real* l, int block, int node, int count) {
    const size_t values = size_t(count) * DdmpNodalValues::count;
    if (block < 0 || nv.gradient_left_out(size_t(block))) return std::fill(l, l + values, Real(0));
    const Real* g = nv.node(size_t(block), node);
    std::copy(g, g + values, l);
  });
}

}  // namespace latmpm::mpm
