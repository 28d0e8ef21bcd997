// A bucket's dense scratch copy of the grid nodes around it: 14×14×14 nodes of 8 lanes
// with fixed strides, so the particle loops address nodes with a few multiply-adds
// instead of hash look-ups. P2G scatters into it and then adds it to the sparse grid;
// G2P first copies the grid into it and then gathers from it.
#pragma once
#include <algorithm>
#include <array>
#include <vector>

#include "mpm/bucket_columns.hpp"
#include "mpm/node_lanes.hpp"
#include "mpm/particle_buckets.hpp"
#include "mpm/shape_ddmp.hpp"
#include "mpm/sparse_grid.hpp"

namespace latmpm::mpm {

// Active-block index of each grid block a bucket's buffer overlaps (4 per axis), −1 if
// inactive.
using BlockTable = std::array<int, 64>;

struct BucketBuffer {
  static constexpr int width = ParticleBuckets::buffer_width;
  static constexpr int stride_j = width * lane::count;
  static constexpr int stride_i = width * stride_j;
  static constexpr int ddmp_values = 9;  // DDMP on the grid: values per node in `ddmp`

  NodeStorage data = NodeStorage(size_t(width) * width * width * lane::count);
  std::array<int, 3> origin{};  // node coordinates of buffer node (0, 0, 0)
  DdmpPartition ddmp_alpha;  // DDMP only: the partition function α (Settings::ddmp_alpha_*)
  DdmpAlphaCache ddmp_alpha_cache;  // DDMP on the grid only: α per point for this pass
  int field = -1;  // grid contact (field_contact.hpp): the velocity field this pass takes; −1: all
  // CPDI1 domains wider than the buffer's stencil box (shape_cpdi.hpp): the scatter lists
  // them here and leaves them to the grid pass after the buckets; the gather reads their
  // nodes from `grid`.
  std::vector<uint32_t> wide_points;
  const SparseGrid* grid = nullptr;
  // DDMP on the grid only (ddmp_grid.hpp): ddmp_values per node, allocated on first use.
  std::vector<Real> ddmp;

  void attach(const Bucket& b) {
    for (int a = 0; a < 3; ++a) origin[a] = ParticleBuckets::cells * b.coord[a] + ParticleBuckets::buffer_lo;
  }
  // Offset (in Reals) of the node with grid coordinates (i, j, k).
  int offset(int i, int j, int k) const {
    return (i - origin[0]) * stride_i + (j - origin[1]) * stride_j + (k - origin[2]) * lane::count;
  }
  // Offset of the node's first value in `ddmp`.
  int ddmp_offset(int i, int j, int k) const {
    return (((i - origin[0]) * width + (j - origin[1])) * width + (k - origin[2])) * ddmp_values;
  }
  // Offset of corner l (bits x, y, z of l) of a cell from the cell's lowest node in `ddmp`.
  static constexpr int ddmp_corner_offset(int l) {
    return (((l >> 2) * width + ((l >> 1) & 1)) * width + (l & 1)) * ddmp_values;
  }
  // The `ddmp` values of the cell whose lowest node is `base`; corner l at ddmp_corner_offset(l).
  Real* ddmp_cell(const int base[3]) { return ddmp.data() + ddmp_offset(base[0], base[1], base[2]); }
  const Real* ddmp_cell(const int base[3]) const { return ddmp.data() + ddmp_offset(base[0], base[1], base[2]); }
};

// First grid block (per axis) a bucket's buffer overlaps.
inline int first_table_block(int bucket_coord) {
  return floor_div(ParticleBuckets::cells * bucket_coord + ParticleBuckets::buffer_lo, SparseGrid::block_width);
}

// Calls fn(block, node, i, j, k, count) for every run of nodes of the bucket's columns (node
// columns, bucket_columns.hpp) that is contiguous in both the grid block and the buffer
// (along k, at most a block wide): `block` the active block's index from the table, `node`
// the run's first node in it ((li · 4 + lj) · 4 + lk), (i, j, k) that node's grid
// coordinates, `count` nodes along k.
template <class Fn>
void for_each_column_run(const Bucket& b, const BucketColumns& columns, const BlockTable& table,
                         const BucketBuffer& buffer, Fn&& fn) {
  constexpr int bw = SparseGrid::block_width;
  int first[3];
  for (int a = 0; a < 3; ++a) first[a] = first_table_block(b.coord[a]);
  for (int i = b.box_lo[0]; i <= b.box_hi[0]; ++i) {
    const int bi = floor_div(i, bw), li = i - bw * bi;
    for (int j = b.box_lo[1]; j <= b.box_hi[1]; ++j) {
      const int bj = floor_div(j, bw), lj = j - bw * bj;
      const size_t column = BucketColumns::index(i - buffer.origin[0], j - buffer.origin[1]);
      const int k_hi = buffer.origin[2] + columns.hi[column];
      for (int k = buffer.origin[2] + columns.lo[column]; k <= k_hi;) {
        const int bk = floor_div(k, bw), lk = k - bw * bk;
        const int count = std::min(bw - lk, k_hi - k + 1);
        const int block = table[((bi - first[0]) * 4 + (bj - first[1])) * 4 + (bk - first[2])];
        fn(block, (li * bw + lj) * bw + lk, i, j, k, count);
        k += count;
      }
    }
  }
}

// Calls fn(grid_nodes, buffer_nodes, count) for every run of for_each_column_run, with the
// grid's lanes of the run (grid_blocks(block) is a block's first lane) and the buffer's.
template <class GridPtr, class Fn>
void for_each_box_run(const Bucket& b, const BucketColumns& columns, const BlockTable& table, GridPtr grid_blocks,
                      BucketBuffer& buffer, Fn&& fn) {
  for_each_column_run(b, columns, table, buffer, [&](int block, int node, int i, int j, int k, int count) {
    fn(grid_blocks(block) + node * lane::count, buffer.data.data() + buffer.offset(i, j, k), count);
  });
}

// Zeroes the buffer nodes of the bucket's columns. Runs are a few nodes long: one SIMD store
// per node beats a call to memset per run (the box passes cost 10 % of a step with the calls).
inline void clear_box(const Bucket& b, const BucketColumns& columns, BucketBuffer& buffer) {
  for (int i = b.box_lo[0]; i <= b.box_hi[0]; ++i)
    for (int j = b.box_lo[1]; j <= b.box_hi[1]; ++j) {
      const size_t column = BucketColumns::index(i - buffer.origin[0], j - buffer.origin[1]);
      const int k_lo = buffer.origin[2] + columns.lo[column], nodes = columns.hi[column] - columns.lo[column] + 1;
      if (nodes <= 0) continue;
      Real* row = buffer.data.data() + buffer.offset(i, j, k_lo);
      for (int n = 0; n < nodes; ++n) store_lanes(row + n * lane::count, NodeLanes{});
    }
}

// Adds the buffer's box into the grid: lanes 0–6 summed, the constraint lane by maximum
// (so the same rigid body wins wherever it touches, independent of order). One node is one
// SIMD value: all lanes summed at once, then the constraint lane replaced by the maximum.
inline void add_box_to_grid(const Bucket& b, const BucketColumns& columns, const BlockTable& table,
                            SparseGrid& grid, BucketBuffer& buffer) {
  for_each_box_run(b, columns, table, [&](int block) { return grid.block(size_t(block)); }, buffer,
                   [](Real* g, const Real* l, int count) {
                     for (int n = 0; n < count; ++n, g += lane::count, l += lane::count) {
                       const NodeLanes grid_node = load_lanes(g), buffer_node = load_lanes(l);
                       NodeLanes sum = grid_node + buffer_node;
                       sum[lane::constraint] = std::max(grid_node[lane::constraint], buffer_node[lane::constraint]);
                       store_lanes(g, sum);
                     }
                   });
}

// Copies the grid's nodes of the bucket's box into the buffer (node by node, as above).
inline void copy_box_from_grid(const Bucket& b, const BucketColumns& columns, const BlockTable& table,
                               const SparseGrid& grid, BucketBuffer& buffer) {
  for_each_box_run(b, columns, table, [&](int block) { return grid.block(size_t(block)); }, buffer,
                   [](const Real* g, Real* l, int count) {
                     for (int n = 0; n < count; ++n) store_lanes(l + n * lane::count, load_lanes(g + n * lane::count));
                   });
}

}  // namespace latmpm::mpm
