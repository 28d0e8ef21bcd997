// DDMP's small-mass nodes (the DDMP group's treatment; docs/solver.md, "DDMP").
//
// Small-mass nodes (Zhang, Ma & Giguere 2011, the nodal transfer coefficients C_li; the
// "distribution coefficient algorithm" of DDMP implementations): the smoothed force reaches
// the nodes one cell outside the material, which have no mass, and a particle that has just
// entered a cell gives its far nodes a mass that vanishes with its distance to the face
// while its α∇S force does not vanish as fast (α ~ d^{2/7}). Such a node l (mass below a
// fraction of ρ h³, not held by a body — or held, but with no mass at all: inside a rigid
// plate of points) gets no acceleration of its own: its mass, momentum
// and force go to the sizeable nodes i around it with coefficients C_li, and after the grid
// update its velocity and velocity change are read back, v_l = Σ_i C_li v_i. The same C
// both ways with Σ_i C_li = 1 keeps mass, momentum and force exactly and makes the
// particles' momentum change equal to the total force; Σ_i C_li x_i = x_l (a linear fit,
// find_ddmp_small_mass_nodes) makes a linear velocity field read back exactly, so the
// smoothed velocity gradient of a surface node sees no spurious shear. Their staged
// lanes and coefficients live in DdmpNodalValues (ddmp_grid.hpp).
#pragma once
#include <tbb/parallel_for.h>

#include <Eigen/Cholesky>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <unordered_map>

#include "mpm/ddmp_grid.hpp"

namespace latmpm::mpm {

namespace ddmp_grid_detail {
constexpr int reach = 2;  // the neighbourhood of a small-mass node: offsets −2 … 2 per axis
constexpr int wide = bw + 2 * reach;  // nodes per axis of a block with that neighbourhood

// C_li for the neighbour i at offset d = i − l, weight w, of a node with coefficients c.
inline Real distribution_coefficient(const Real* c, int x, int y, int z, Real w) {
  return w * (c[0] + c[1] * x + c[2] * y + c[3] * z);
}
inline Real* coefficients_of(DdmpNodalValues& nv, size_t b, int n) {
  return nv.coefficients.data() + (b * SparseGrid::nodes_per_block + size_t(n)) * 4;
}

template <int Components>
using WideHalo = BlockHalo<reach, Components>;

// Whether block b or one of its neighbours holds a node that hands on (most blocks: none).
inline bool near_small_mass(const DdmpNodalValues& nv, size_t b) {
  for (int nb : nv.neighbours[b])
    if (nb >= 0 && nv.block_has_small[size_t(nb)]) return true;
  return false;
}
// w(d) = 2^(−|d|₁) of an offset d within reach.
inline Real offset_weight(int x, int y, int z) {
  static constexpr Real w[3 * reach + 1] = {1, 0.5, 0.25, 0.125, 0.0625, 0.03125, 0.015625};
  return w[std::abs(x) + std::abs(y) + std::abs(z)];
}
// The 124 offsets d ≠ 0 within two cells per axis: a node one cell outside a flat face sees
// two layers of the material along the normal (a linear fit), and every node next to a
// particle's cell sees sizeable nodes even where a particle has just entered a new cell.
struct Offset {
  int x, y, z;
  Real weight;  // 2^(−|d|₁)
};
constexpr int offset_count = 124;
inline const std::array<Offset, offset_count>& neighbour_offsets() {
  static const auto list = [] {
    std::array<Offset, offset_count> out{};
    size_t n = 0;
    for (int x = -reach; x <= reach; ++x)
      for (int y = -reach; y <= reach; ++y)
        for (int z = -reach; z <= reach; ++z) {
          const int l1 = std::abs(x) + std::abs(y) + std::abs(z);
          if (l1 > 0) out[n++] = {x, y, z, offset_weight(x, y, z)};
        }
    return out;
  }();
  return list;
}
// Calls fn(x, y, z, w) for those offsets and their weights.
template <class Fn>
[[gnu::always_inline]] inline void for_each_offset(Fn&& fn) {
  for (const Offset& o : neighbour_offsets()) fn(o.x, o.y, o.z, o.weight);
}

// The pattern of a small-mass node's neighbourhood: bit o set when the neighbour at
// neighbour_offsets()[o] is sizeable (o < 124), bit 127 when the node holds mass of its
// own. Its distribution coefficients are a function of this alone (fit_distribution).
struct NeighbourPattern {
  uint64_t bits[2] = {0, 0};
  bool operator==(const NeighbourPattern& o) const { return bits[0] == o.bits[0] && bits[1] == o.bits[1]; }
  bool sizeable(int o) const { return (bits[o >> 6] >> (o & 63)) & 1; }
};
struct NeighbourPatternHash {
  size_t operator()(const NeighbourPattern& p) const {
    return size_t(p.bits[0] * 0x9E3779B97F4A7C15ull ^ (p.bits[1] + 0x632BE59BD9B4E019ull + (p.bits[0] >> 7)));
  }
};
using Fit = std::array<Real, 4>;

// (c₀, c) of the weighted least-squares fit over the pattern's sizeable neighbours (zero:
// none, the node does not hand on); the weighted mean where they do not span 3D or where a
// node with mass would give a neighbour a negative share (find_ddmp_small_mass_nodes).
inline Fit fit_distribution(const NeighbourPattern& pattern) {
  const auto& offsets = neighbour_offsets();
  Eigen::Matrix4d A = Eigen::Matrix4d::Zero();
  for (int o = 0; o < offset_count; ++o) {
    if (!pattern.sizeable(o)) continue;
    const Offset& d = offsets[size_t(o)];
    const Eigen::Vector4d basis(1, d.x, d.y, d.z);
    A.noalias() += d.weight * basis * basis.transpose();
  }
  if (!(A(0, 0) > 0)) return {0, 0, 0, 0};
  const Eigen::LDLT<Eigen::Matrix4d> ldlt(A);
  const Eigen::Vector4d diagonal = ldlt.vectorD();
  Eigen::Vector4d fit = Eigen::Vector4d::Zero();
  if (ldlt.info() == Eigen::Success && diagonal.minCoeff() > 1e-6 * diagonal.maxCoeff())
    fit = ldlt.solve(Eigen::Vector4d(1, 0, 0, 0));
  // A node with mass hands it on too: a negative C_li could leave a receiver with none.
  // Such a node takes the weighted mean (a node outside the material has none).
  bool negative = false;
  if (pattern.sizeable(127) && fit[0] != 0)
    for (int o = 0; o < offset_count; ++o) {
      const Offset& d = offsets[size_t(o)];
      if (pattern.sizeable(o)) negative |= distribution_coefficient(fit.data(), d.x, d.y, d.z, d.weight) < 0;
    }
  if (fit[0] == 0 || negative) fit = Eigen::Vector4d(1 / A(0, 0), 0, 0, 0);
  return {fit[0], fit[1], fit[2], fit[3]};
}

// fit_distribution, remembered per thread: a surface has few patterns (a flat face, its
// edges and corners, a particle entering a cell), so the 4×4 solves run once per pattern,
// not once per node and step. A pure function of the pattern: results do not depend on
// what a thread has seen.
inline const Fit& remembered_fit(const NeighbourPattern& pattern) {
  thread_local std::unordered_map<NeighbourPattern, Fit, NeighbourPatternHash> memo;
  if (memo.size() > (size_t(1) << 16)) memo.clear();  // a bound on memory, never reached in practice
  const auto it = memo.find(pattern);
  if (it != memo.end()) return it->second;
  return memo.emplace(pattern, fit_distribution(pattern)).first->second;
}
}  // namespace ddmp_grid_detail

// Finds the nodes that hand on their lanes — mass below `small_mass` and not held by a body
// (lane::constraint), or held with no mass at all; a node with mass within one cell (else
// neither their force nor their velocity enters anything), sizeable nodes (mass ≥
// small_mass) among its 124 neighbours (neighbour_offsets) — and their distribution
// coefficients C_li = w(d) (c₀ + c · d), d = i − l in cells over those sizeable nodes i,
// w(d) = 2^(−|d|₁): the weighted least-squares fit of a linear field, so that
// Σ_i C_li = 1 and Σ_i C_li x_i = x_l — a node outside a free surface reads back the linear
// extrapolation of the material's velocity, which keeps Eq. 8's exactness for linear fields
// in L. Where the sizeable nodes do not span 3D (a plate one node thick), or where the node
// has mass of its own and the fit would give a neighbour a negative share of it,
// C_li = w(d) / Σ w: their weighted mean.
inline void find_ddmp_small_mass_nodes(const SparseGrid& grid, Real small_mass, DdmpNodalValues& nv) {
  using namespace ddmp_grid_detail;
  tbb::parallel_for(size_t(0), grid.block_count(), [&](size_t b) {
    const Real* block = grid.block(b);
    std::fill_n(coefficients_of(nv, b, 0), 4 * SparseGrid::nodes_per_block, Real(0));
    nv.block_has_small[b] = 0;
    // A node hands on when its mass is small and no body holds it, or when a body holds it
    // but no deformable point gives it mass (a node inside a rigid plate of points, one
    // cell beyond the material: docs/solver.md, "Held nodes without mass").
    const auto hands_on = [&](int n) {
      const Real m = block[n * lane::count + lane::mass];
      return m < small_mass && (block[n * lane::count + lane::constraint] == 0 || m == 0);
    };
    bool any = false;
    for (int n = 0; n < SparseGrid::nodes_per_block; ++n) any |= hands_on(n);
    if (!any) return;
    WideHalo<1> mass;
    load_halo<reach, 1>(nv, b, [&](size_t nb, int n) { return grid.block(nb) + n * lane::count + lane::mass; }, mass);
    const auto& offsets = neighbour_offsets();
    for (int i = 0; i < bw; ++i)
      for (int j = 0; j < bw; ++j)
        for (int k = 0; k < bw; ++k) {
          const int n = (i * bw + j) * bw + k;
          if (!hands_on(n)) continue;
          bool touches_mass = false;  // a node with mass within one cell: its L or force matters
          for (int x = -1; x <= 1; ++x)
            for (int y = -1; y <= 1; ++y)
              for (int z = -1; z <= 1; ++z) touches_mass |= mass.at(i + x, j + y, k + z)[0] > 0;
          if (!touches_mass) continue;
          NeighbourPattern pattern;
          for (int o = 0; o < offset_count; ++o) {
            const Offset& d = offsets[size_t(o)];
            if (mass.at(i + d.x, j + d.y, k + d.z)[0] >= small_mass) pattern.bits[o >> 6] |= uint64_t(1) << (o & 63);
          }
          if (block[n * lane::count + lane::mass] > 0) pattern.bits[1] |= uint64_t(1) << 63;
          const Fit& fit = remembered_fit(pattern);
          if (fit[0] == 0) continue;
          std::copy(fit.begin(), fit.end(), coefficients_of(nv, b, n));
          nv.block_has_small[b] = 1;
        }
  });
}

// Hands lanes [first, first + count) of every small-mass node on to its sizeable
// neighbours, C_li times each, and zeroes them (mass, momentum and force after P2G; the
// remapped momentum of MUSL).
inline void move_ddmp_small_mass_lanes(SparseGrid& grid, Real small_mass, int first, int count, DdmpNodalValues& nv) {
  using namespace ddmp_grid_detail;
  tbb::parallel_for(size_t(0), grid.block_count(), [&](size_t b) {  // stage and clear the sources
    if (!nv.block_has_small[b]) return;
    for (int n = 0; n < SparseGrid::nodes_per_block; ++n) {
      if (coefficients_of(nv, b, n)[0] == 0) continue;
      Real* node = grid.block(b) + n * lane::count;
      Real* staged = nv.node(b, n);
      for (int c = 0; c < count; ++c) staged[c] = node[first + c], node[first + c] = 0;
    }
  });
  tbb::parallel_for(size_t(0), grid.block_count(), [&](size_t b) {  // receivers pull their part
    if (!near_small_mass(nv, b)) return;
    // The sources within reach of this block (halo order: the same order for every
    // receiver, so the sums do not depend on threads), then each source's part to the
    // block's sizeable nodes within two cells of it.
    IndexHalo<reach> nodes;
    load_index_halo(nv, b, nodes);
    Real* block = grid.block(b);
    for (int si = -reach; si < bw + reach; ++si)
      for (int sj = -reach; sj < bw + reach; ++sj)
        for (int sk = -reach; sk < bw + reach; ++sk) {
          const int32_t l = nodes.at(si, sj, sk);
          if (l < 0) continue;
          const Real* c = nv.coefficients.data() + size_t(l) * 4;
          if (c[0] == 0) continue;
          const Real* staged = nv.values.data() + size_t(l) * DdmpNodalValues::count;
          for (int i = std::max(0, si - reach); i <= std::min(bw - 1, si + reach); ++i)
            for (int j = std::max(0, sj - reach); j <= std::min(bw - 1, sj + reach); ++j)
              for (int k = std::max(0, sk - reach); k <= std::min(bw - 1, sk + reach); ++k) {
                const int x = i - si, y = j - sj, z = k - sk;  // d = i − l
                if (x == 0 && y == 0 && z == 0) continue;
                Real* node = block + SparseGrid::node_offset(i, j, k);
                if (!(node[lane::mass] >= small_mass)) continue;
                const Real C = distribution_coefficient(c, x, y, z, offset_weight(x, y, z));
                for (int q = 0; q < count; ++q) node[first + q] += C * staged[q];
              }
        }
  });
}

// Lanes [first, first + count) of every small-mass node from its sizeable neighbours,
// v_l = Σ_i C_li v_i (the new velocity and its change after the grid update; MUSL's
// remapped velocity).
inline void spread_ddmp_small_mass_lanes(SparseGrid& grid, Real small_mass, int first, int count, DdmpNodalValues& nv) {
  using namespace ddmp_grid_detail;
  tbb::parallel_for(size_t(0), grid.block_count(), [&](size_t b) {
    if (!nv.block_has_small[b]) return;
    IndexHalo<reach> nodes;
    load_index_halo(nv, b, nodes);
    const Real* lanes = grid.block(0);
    for (int i = 0; i < bw; ++i)
      for (int j = 0; j < bw; ++j)
        for (int k = 0; k < bw; ++k) {
          const int n = (i * bw + j) * bw + k;
          const Real* c = coefficients_of(nv, b, n);
          if (c[0] == 0) continue;
          Real* staged = nv.node(b, n);
          for (int q = 0; q < count; ++q) staged[q] = 0;
          for_each_offset([&](int x, int y, int z, Real w) {
            const int32_t other_node = nodes.at(i + x, j + y, k + z);
            if (other_node < 0) return;
            const Real* other = lanes + size_t(other_node) * lane::count;
            if (!(other[lane::mass] >= small_mass)) return;
            const Real C = distribution_coefficient(c, x, y, z, w);
            for (int q = 0; q < count; ++q) staged[q] += C * other[first + q];
          });
        }
  });
  tbb::parallel_for(size_t(0), grid.block_count(), [&](size_t b) {
    if (!nv.block_has_small[b]) return;
    for (int n = 0; n < SparseGrid::nodes_per_block; ++n) {
      if (coefficients_of(nv, b, n)[0] == 0) continue;
      Real* node = grid.block(b) + n * lane::count;
      const Real* staged = nv.node(b, n);
      for (int q = 0; q < count; ++q) node[first + q] = staged[q];
    }
  });
}

}  // namespace latmpm::mpm
