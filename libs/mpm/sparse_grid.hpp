// The sparse background grid: nodes at x = i·h (the origin is a node), stored in blocks of
// 4×4×4 nodes keyed by block coordinates. Only blocks that particles' stencils reach hold
// memory, so memory grows with the material, not with its bounding box, and there is no
// domain to declare. Blocks are kept sorted by key, which makes every pass over them
// deterministic and lets the grid be split into block ranges later (MPI).
//
// Each node holds `lanes` values. During a step they mean (docs/solver.md, "Grid"):
//   after particles-to-grid:  m, p_x, p_y, p_z, f_x, f_y, f_z, constraint
//   after the grid update:    m, v_x, v_y, v_z, Δv_x, Δv_y, Δv_z, constraint
// with p the momentum, f the internal + external force, v the new velocity, Δv its change
// over the step, and constraint = 1 + index of the rigid body whose points touch the node
// (0 = free). Eight lanes make one node a 64-byte cache line.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "core/large_pages.hpp"
#include "mpm/real.hpp"

namespace latmpm::mpm {

// Node storage starts on a cache line, so each node's 8 lanes are one 64-byte line. With
// std::vector's allocator the grid and the bucket buffers began 16 bytes past a line (glibc's
// large blocks) and every node load and store of the node loops spanned two lines; aligned,
// the uGIMP step takes 2–4 % less CPU with the same bits (docs/benchmarks.md, "What bounds
// the uGIMP rate"). A large grid lies on 2 MB pages (core/large_pages.hpp): its blocks are
// visited out of order, a 4 kB page each.
using NodeStorage = std::vector<Real, LargePageAllocator<Real>>;

namespace lane {
inline constexpr int mass = 0;
inline constexpr int momentum = 1;  // 3 lanes; velocity after the grid update
inline constexpr int force = 4;     // 3 lanes; velocity change after the grid update
inline constexpr int constraint = 7;
inline constexpr int count = 8;
}  // namespace lane

// Floor division that is right for negative grid coordinates.
inline int floor_div(int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

class SparseGrid {
 public:
  static constexpr int block_width = 4;  // nodes per axis in a block
  static constexpr int nodes_per_block = block_width * block_width * block_width;
  static constexpr int reals_per_block = nodes_per_block * lane::count;
  using Coord = std::array<int, 3>;

  // Key of the block holding node (i, j, k); blocks within ±2^20 of the origin per axis.
  static uint64_t block_key(int bx, int by, int bz);
  static Coord key_to_coord(uint64_t key);
  static constexpr int max_block_coord = (1 << 20) - 1;

  // Makes exactly these blocks (sorted, unique keys) active. Storage is reused when the
  // set is unchanged; values are not preserved (every step starts from a zeroed grid).
  void set_active_blocks(const std::vector<uint64_t>& sorted_keys);
  // Index of the active block with these block coordinates, or -1.
  int find(int bx, int by, int bz) const;

  size_t block_count() const { return keys_.size(); }
  // Names this set of active blocks: it changes whenever set_active_blocks changes the set,
  // and no two sets, of this grid or any other, share one (for caches of per-block look-ups).
  uint64_t layout() const { return layout_; }
  uint64_t key(size_t b) const { return keys_[b]; }
  Coord coord(size_t b) const { return key_to_coord(keys_[b]); }
  Real* block(size_t b) { return data_.data() + b * reals_per_block; }
  const Real* block(size_t b) const { return data_.data() + b * reals_per_block; }
  // Where node (i, j, k)'s lanes start in the block storage (in Reals; the same index in any
  // array laid out like the grid's, e.g. a contact field's copy), or -1 when its block is inactive.
  std::ptrdiff_t node_index(int i, int j, int k) const {
    const int bi = floor_div(i, block_width), bj = floor_div(j, block_width), bk = floor_div(k, block_width);
    const int b = find(bi, bj, bk);
    if (b < 0) return -1;
    return std::ptrdiff_t(b) * reals_per_block +
           node_offset(i - block_width * bi, j - block_width * bj, k - block_width * bk);
  }
  // The lanes of node (i, j, k) (grid coordinates), or nullptr when its block is inactive.
  const Real* node(int i, int j, int k) const {
    const std::ptrdiff_t at = node_index(i, j, k);
    return at < 0 ? nullptr : data_.data() + at;
  }
  Real* node(int i, int j, int k) { return const_cast<Real*>(static_cast<const SparseGrid&>(*this).node(i, j, k)); }
  // Offset of node (li, lj, lk), 0 ≤ l < block_width, inside a block, in Reals.
  static int node_offset(int li, int lj, int lk) {
    return ((li * block_width + lj) * block_width + lk) * lane::count;
  }
  // World position (m) of node (i, j, k) for cell size h.
  static Vec3 node_position(int i, int j, int k, Real h) { return Vec3(i * h, j * h, k * h); }

  size_t memory_bytes() const;
  // Exchanges the node lanes with `other` (grid contact's per-field lanes, field_contact.hpp,
  // take the grid's place for a field's passes); `other` must hold as many Reals.
  void swap_lanes(NodeStorage& other) { data_.swap(other); }
  size_t lane_values() const { return data_.size(); }

 private:
  std::vector<uint64_t> keys_;
  NodeStorage data_;
  std::unordered_map<uint64_t, int> index_;
  uint64_t layout_ = 0;  // 0: no block set yet
};

}  // namespace latmpm::mpm
