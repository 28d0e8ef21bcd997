// Which grid cells are at least half filled with deformable material this step: DDMP's
// integration domain Ω (shape_ddmp.hpp). The points' initial volumes summed per cell (the
// cell named by its lowest node, 64 per active grid block), compared with h³/2 when copied
// per bucket into its buffer, from which each particle reads the 27 cells around its own.
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

// Sums the initial volume V0 of the deformable points (`deformable[body]`) per cell, into
// 64 values per active grid block (the cells' lowest nodes lie in active blocks: every
// stencil reaches its own cell's nodes). Colour by colour, like the scatter: buckets of one
// colour never share a cell, and each cell adds its points in a fixed order.
inline void mark_occupied_cells(const ParticleBuckets& buckets, const std::vector<BlockTable>& tables,
                                const Particles& ps, const std::vector<bool>& deformable, Real h,
                                std::vector<Real>& cell_volume, size_t block_count) {
  cell_volume.assign(block_count * SparseGrid::nodes_per_block, 0);
  const Real inv_h = 1 / h;
  const auto& list = buckets.buckets();
  for (const auto& colour : buckets.colours())
    tbb::parallel_for(tbb::blocked_range<size_t>(0, colour.size(), 1), [&](const tbb::blocked_range<size_t>& r) {
      for (size_t c = r.begin(); c < r.end(); ++c) {
        const size_t bi = colour[c];
        const Bucket& b = list[bi];
        for (uint32_t q = b.run_begin; q < b.run_end; ++q) {
          const BodyRun& run = buckets.runs()[q];
          if (!deformable[size_t(run.body)]) continue;
          for (uint32_t p = run.begin; p < run.end; ++p) {
            const auto cell = cell_of(ps.position[p], inv_h);
            const int block = tables[bi][size_t(occupancy_detail::table_index(b, cell[0], cell[1], cell[2]))];
            if (block >= 0)
              cell_volume[size_t(block) * SparseGrid::nodes_per_block +
                          size_t(occupancy_detail::local_bit(cell[0], cell[1], cell[2]))] += ps.volume0[p];
          }
        }
      }
    });
}

// Marks the bucket's buffer cells that belong to Ω: at least half filled, Σ V0 ≥ h³/2; and
// gives the buffer the run's partition function α. `widen_below`: cells that many further
// below the bucket's box (DdmpGridShape's box starts at the particles' own cells).
inline void fill_occupancy(const Bucket& b, const BlockTable& table, const std::vector<Real>& cell_volume,
                           Real h, const DdmpPartition& alpha, BucketBuffer& buffer, int widen_below = 0) {
  buffer.ddmp_alpha = alpha;
  constexpr int w = BucketBuffer::width;
  const Real half_cell = Real(0.5) * h * h * h;
  buffer.occupied.assign(size_t(w) * w * w, 0);
  // Only the bucket's node box (its particles' cells widened by the stencil's reach, which
  // holds every cell a particle's 27-cell neighbourhood can name).
  for (int gi = b.box_lo[0] - widen_below; gi <= b.box_hi[0]; ++gi)
    for (int gj = b.box_lo[1] - widen_below; gj <= b.box_hi[1]; ++gj)
      for (int gk = b.box_lo[2] - widen_below; gk <= b.box_hi[2]; ++gk) {
        const int i = gi - buffer.origin[0], j = gj - buffer.origin[1], k = gk - buffer.origin[2];
        const int block = table[size_t(occupancy_detail::table_index(b, gi, gj, gk))];
        if (block >= 0)
          buffer.occupied[size_t((i * w + j) * w + k)] =
              cell_volume[size_t(block) * SparseGrid::nodes_per_block + size_t(occupancy_detail::local_bit(gi, gj, gk))] >=
              half_cell;
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
