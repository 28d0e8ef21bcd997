#include "mpm/bucket_partition.hpp"

#include <algorithm>

#include "mpm/particle_buckets.hpp"
#include "mpm/sparse_grid.hpp"

namespace latmpm::mpm {

namespace {
constexpr int axis_bits = 21;
constexpr int axis_offset = 1 << 20;

// The low 21 bits of v spread to every third bit (bit i to bit 3i).
uint64_t spread_bits(uint64_t v) {
  v &= (uint64_t(1) << axis_bits) - 1;
  v = (v | (v << 32)) & 0x1f00000000ffffULL;
  v = (v | (v << 16)) & 0x1f0000ff0000ffULL;
  v = (v | (v << 8)) & 0x100f00f00f00f00fULL;
  v = (v | (v << 4)) & 0x10c30c30c30c30c3ULL;
  v = (v | (v << 2)) & 0x1249249249249249ULL;
  return v;
}
}  // namespace

uint64_t morton_key(const std::array<int, 3>& bucket) {
  return (spread_bits(uint64_t(bucket[0] + axis_offset)) << 2) | (spread_bits(uint64_t(bucket[1] + axis_offset)) << 1) |
         spread_bits(uint64_t(bucket[2] + axis_offset));
}

std::array<int, 3> bucket_of(const Vec3& x, Real inv_h) {
  const auto cell = cell_of(x, inv_h);
  return {floor_div(cell[0], ParticleBuckets::cells), floor_div(cell[1], ParticleBuckets::cells),
          floor_div(cell[2], ParticleBuckets::cells)};
}

uint64_t bucket_order_key(const Bucket& bucket) {
  return SparseGrid::block_key(bucket.coord[0], bucket.coord[1], bucket.coord[2]);
}

std::vector<uint64_t> bucket_order_keys(const std::vector<Bucket>& buckets) {
  std::vector<uint64_t> keys;
  keys.reserve(buckets.size());
  for (const Bucket& b : buckets) keys.push_back(bucket_order_key(b));
  return keys;
}

int BucketPartition::owner(uint64_t key) const {
  return int(std::upper_bound(cuts.begin(), cuts.end(), key) - cuts.begin());
}

BucketPartition partition_buckets(const std::vector<std::pair<uint64_t, uint64_t>>& counts, int parts) {
  uint64_t total = 0;
  for (const auto& c : counts) total += c.second;
  BucketPartition out;
  uint64_t running = 0;
  size_t next = 0;  // first bucket not yet placed
  for (int r = 1; r < parts; ++r) {
    // Range r − 1 ends once the running count reaches r/parts of the total (at least one
    // bucket per range while buckets last, so no process is left empty needlessly).
    const uint64_t share = (total * uint64_t(r) + uint64_t(parts) - 1) / uint64_t(parts);
    bool placed = false;
    while (next < counts.size() && (running < share || !placed)) running += counts[next++].second, placed = true;
    // The cut is the key after the last bucket placed; past the end: an empty range.
    out.cuts.push_back(next < counts.size() ? counts[next].first : ~uint64_t(0));
  }
  return out;
}

}  // namespace latmpm::mpm
