// Which nodes of a bucket's box its particles' stencils reach, column by column: for every
// (i, j) of the bucket's buffer (bucket_buffer.hpp), the k-range of the occupied cells (as
// the gather records them) or of the nodes their stencils reach (what the box passes move).
//
// Why: the box passes (clear, add to the grid, copy from the grid) cost per node, and a
// bucket's box is the bounding box of its particles' stencils. In a solid block that is
// 0.33 nodes per particle; a lattice's thin struts cross buckets diagonally and leave most
// of the box empty: 1.52 box nodes per particle in T2P30 at the paper's resolution, where
// the box passes took 23 % of a step (docs/benchmarks.md, "Paper-resolution T2P30 against
// the cube"). The column ranges hold 1.08 nodes per particle there. Every node a stencil
// reaches is inside its column's range, and a node outside every stencil holds zeros in
// the scatter and is never read by the gather, so the passes over the columns give the
// same grid, bit for bit, as the passes over the box.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>

#include "mpm/particle_buckets.hpp"
#include "mpm/sparse_grid.hpp"

namespace latmpm::mpm {

struct BucketColumns {
  static constexpr int width = ParticleBuckets::buffer_width;  // buffer coordinates 0 … width − 1
  // Rows of `stride` bytes: column (i, j) at i · stride + pad_below + j. The pads hold empty
  // columns, so stencil_columns shifts whole rows: a node column takes the cell columns up
  // to 3 below and 1 above it (cpGIMP's reach, the widest).
  static constexpr int pad_below = 3, pad_above = 1, stride = width + pad_below + pad_above;
  static constexpr size_t size = size_t(width) * stride;
  static size_t index(int i, int j) { return size_t(i * stride + pad_below + j); }
  // Per column: the lowest and highest k (buffer coordinates); lo > hi if empty.
  std::array<int8_t, size> lo, hi;

  BucketColumns() { clear(); }
  void clear() { lo.fill(int8_t(width)), hi.fill(int8_t(-1)); }
  void add(int i, int j, int k) {
    const size_t c = index(i, j);
    lo[c] = std::min(lo[c], int8_t(k));
    hi[c] = std::max(hi[c], int8_t(k));
  }
  // Records a particle's cell (grid coordinates); the cell must be within the bucket's drift
  // limit (ParticleBuckets::within_drift), which keeps it in the buffer.
  void add_cell(const Bucket& b, const std::array<int, 3>& cell) {
    add(cell[0] - first_node(b, 0), cell[1] - first_node(b, 1), cell[2] - first_node(b, 2));
  }
  void merge(const BucketColumns& o) {
    for (size_t c = 0; c < size; ++c) lo[c] = std::min(lo[c], o.lo[c]), hi[c] = std::max(hi[c], o.hi[c]);
  }
  // Grid node coordinate of buffer coordinate 0 along axis a.
  static int first_node(const Bucket& b, int a) {
    return ParticleBuckets::cells * b.coord[a] + ParticleBuckets::buffer_lo;
  }
};

// The node columns the stencils of the cells in `cells` reach: a particle in cell c touches
// nodes c + below … c + above per axis (Shape::reach_below, reach_above). Node column n takes
// the cell columns n − above … n − below, along j and then along i, as shifts of the whole
// arrays (a few vector instructions a bucket: computed per step for every bucket).
template <int below, int above>
BucketColumns stencil_columns(const BucketColumns& cells) {
  static_assert(-below <= BucketColumns::pad_above && above <= BucketColumns::pad_below, "the pads hold the reach");
  using C = BucketColumns;
  auto spread = [](const C& from, C& to, int shift_below, int shift_above, int step) {
    for (int d = shift_below; d <= shift_above; ++d) {
      const int s = d * step;  // to[x] takes from[x − s]
      for (int x = std::max(s, 0), end = std::min(int(C::size), int(C::size) + s); x < end; ++x) {
        to.lo[size_t(x)] = std::min(to.lo[size_t(x)], from.lo[size_t(x - s)]);
        to.hi[size_t(x)] = std::max(to.hi[size_t(x)], from.hi[size_t(x - s)]);
      }
    }
  };
  C along_j;
  spread(cells, along_j, below, above, 1);  // within rows: the pads keep rows apart
  for (int i = 0; i < C::width; ++i)        // the pads again empty for the shift along i
    for (int p : {-3, -2, -1, C::width}) along_j.lo[C::index(i, p)] = int8_t(C::width), along_j.hi[C::index(i, p)] = -1;
  C nodes;
  spread(along_j, nodes, below, above, C::stride);
  for (size_t x = 0; x < C::size; ++x)
    if (nodes.lo[x] <= nodes.hi[x])
      nodes.lo[x] = int8_t(std::max(nodes.lo[x] + below, 0)), nodes.hi[x] = int8_t(std::min(nodes.hi[x] + above, C::width - 1));
  return nodes;
}

// Adds the keys of the grid blocks that hold a node of the bucket's node columns (its k-ranges,
// as stencil_columns gives them) or one within `Halo` nodes of such a node. Not the blocks of
// the bucket's box: thin struts cross a box diagonally, and in T2P30 at the paper's cell the
// box's blocks are 1.32 times those the columns reach; every whole-grid pass (the node update,
// DDMP's smoothing and small-mass passes, the clears) runs over them. A node that no stencil
// reaches holds zeros and is read by no point, so leaving its block out changes no value.
template <int Halo>
void add_column_blocks(const Bucket& b, const BucketColumns& columns, std::vector<uint64_t>& keys) {
  constexpr int bw = SparseGrid::block_width, w = BucketColumns::width;
  // The blocks the buffer and its halo can touch, as a mask: 14 + 2 halo nodes span 5 blocks.
  constexpr int span = (w + 2 * Halo + bw - 1) / bw + 1;
  int origin[3], first[3];
  for (int a = 0; a < 3; ++a) {
    origin[a] = BucketColumns::first_node(b, a);
    first[a] = floor_div(origin[a] - Halo, bw);
  }
  std::array<bool, span * span * span> used{};
  for (int i = 0; i < w; ++i)
    for (int j = 0; j < w; ++j) {
      const size_t column = BucketColumns::index(i, j);
      if (columns.lo[column] > columns.hi[column]) continue;
      const int k_lo = floor_div(origin[2] + columns.lo[column] - Halo, bw) - first[2];
      const int k_hi = floor_div(origin[2] + columns.hi[column] + Halo, bw) - first[2];
      for (int bi = floor_div(origin[0] + i - Halo, bw); bi <= floor_div(origin[0] + i + Halo, bw); ++bi)
        for (int bj = floor_div(origin[1] + j - Halo, bw); bj <= floor_div(origin[1] + j + Halo, bw); ++bj)
          for (int bk = k_lo; bk <= k_hi; ++bk)
            used[size_t(((bi - first[0]) * span + (bj - first[1])) * span + bk)] = true;
    }
  for (int i = 0; i < span; ++i)
    for (int j = 0; j < span; ++j)
      for (int k = 0; k < span; ++k)
        if (used[size_t((i * span + j) * span + k)])
          keys.push_back(SparseGrid::block_key(first[0] + i, first[1] + j, first[2] + k));
}

}  // namespace latmpm::mpm
