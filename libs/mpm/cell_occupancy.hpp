// Which grid cells hold deformable material this step: DDMP's integration domain Ω
// (shape_ddmp.hpp). One 64-bit mask per active grid block, bit n for the cell whose lowest
// node is node n of the block; copied per bucket into its buffer, from which each particle
// reads the 27 cells around its own.
#pragma once
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cstdint>
#include <vector>

#include "mpm/body.hpp"
#include "mpm/bucket_buffer.hpp"
#include "mpm/particles.hpp"
#include "mpm/shape_ddmp.hpp"
#include "mpm/sparse_grid.hpp"

namespace latmpm::mpm {

namespace occupancy_detail {
inline int local_bit(int i, int j, int k) {
  constexpr int bw = SparseGrid::block_width;
  return ((i - bw * floor_div(i, bw)) * bw + (j - bw * floor_div(j, bw))) * bw + (k - bw * floor_div(k, bw));
}
inline int table_index(const Bucket& b, int i, int j, int k) {
  constexpr int bw = SparseGrid::block_width;
  return ((floor_div(i, bw) - first_table_block(b.coord[0])) * 4 + (floor_div(j, bw) - first_table_block(b.coord[1]))) * 4 +
         (floor_div(k, bw) - first_table_block(b.coord[2]));
}
}  // namespace occupancy_detail

// Marks the cells of the deformable particles (`deformable[body]`). The cells' lowest nodes
// lie in active blocks (every stencil reaches its own cell's nodes). Bits are set with an
// atomic OR: the result does not depend on the order.
inline void mark_occupied_cells(const ParticleBuckets& buckets, const std::vector<BlockTable>& tables,
                                const Particles& ps, const std::vector<bool>& deformable, Real h,
                                std::vector<uint64_t>& occupancy, size_t block_count) {
  occupancy.assign(block_count, 0);
  const Real inv_h = 1 / h;
  const auto& list = buckets.buckets();
  tbb::parallel_for(tbb::blocked_range<size_t>(0, list.size(), 1), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t bi = r.begin(); bi < r.end(); ++bi) {
      const Bucket& b = list[bi];
      for (uint32_t q = b.run_begin; q < b.run_end; ++q) {
        const BodyRun& run = buckets.runs()[q];
        if (!deformable[size_t(run.body)]) continue;
        uint64_t last_bits = 0;
        int last_block = -1;
        for (uint32_t p = run.begin; p < run.end; ++p) {
          const auto c = cell_of(ps.position[p], inv_h);
          const int block = tables[bi][size_t(occupancy_detail::table_index(b, c[0], c[1], c[2]))];
          if (block < 0) continue;
          const uint64_t bit = uint64_t(1) << occupancy_detail::local_bit(c[0], c[1], c[2]);
          if (block == last_block && (last_bits & bit)) continue;  // sorted by cell: skip repeats
          __atomic_fetch_or(&occupancy[size_t(block)], bit, __ATOMIC_RELAXED);
          last_block = block;
          last_bits = bit;
        }
      }
    }
  });
}

// Copies the occupancy of the bucket's buffer cells from the per-block masks.
inline void fill_occupancy(const Bucket& b, const BlockTable& table, const std::vector<uint64_t>& occupancy,
                           BucketBuffer& buffer) {
  constexpr int w = BucketBuffer::width;
  buffer.occupied.assign(size_t(w) * w * w, 0);
  for (int i = 0; i < w; ++i)
    for (int j = 0; j < w; ++j)
      for (int k = 0; k < w; ++k) {
        const int gi = buffer.origin[0] + i, gj = buffer.origin[1] + j, gk = buffer.origin[2] + k;
        const int block = table[size_t(occupancy_detail::table_index(b, gi, gj, gk))];
        if (block >= 0)
          buffer.occupied[size_t((i * w + j) * w + k)] =
              uint8_t((occupancy[size_t(block)] >> occupancy_detail::local_bit(gi, gj, gk)) & 1u);
      }
}

// The 27-bit mask (ddmp_cell_bit) of occupied cells around the cell of x.
inline uint32_t occupancy_around(const BucketBuffer& buffer, const Vec3& x, Real inv_h) {
  constexpr int w = BucketBuffer::width;
  const auto c = cell_of(x, inv_h);
  uint32_t mask = 0;
  for (int dx = -1; dx <= 1; ++dx)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dz = -1; dz <= 1; ++dz) {
        const int i = c[0] + dx - buffer.origin[0], j = c[1] + dy - buffer.origin[1], k = c[2] + dz - buffer.origin[2];
        if (buffer.occupied[size_t((i * w + j) * w + k)]) mask |= uint32_t(1) << ddmp_cell_bit(dx, dy, dz);
      }
  return mask;
}

}  // namespace latmpm::mpm
