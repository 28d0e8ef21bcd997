#include "mpm/sparse_grid.hpp"

#include <atomic>

namespace latmpm::mpm {

namespace {
constexpr int coord_bits = 21;
constexpr uint64_t coord_mask = (uint64_t(1) << coord_bits) - 1;
constexpr int coord_offset = 1 << 20;
}  // namespace

uint64_t SparseGrid::block_key(int bx, int by, int bz) {
  // x most significant: sorting keys orders blocks x-major like the particles' buckets.
  return (uint64_t(bx + coord_offset) << (2 * coord_bits)) |
         (uint64_t(by + coord_offset) << coord_bits) | uint64_t(bz + coord_offset);
}

SparseGrid::Coord SparseGrid::key_to_coord(uint64_t key) {
  return {int((key >> (2 * coord_bits)) & coord_mask) - coord_offset,
          int((key >> coord_bits) & coord_mask) - coord_offset, int(key & coord_mask) - coord_offset};
}

void SparseGrid::set_active_blocks(const std::vector<uint64_t>& sorted_keys) {
  if (sorted_keys == keys_) return;
  keys_ = sorted_keys;
  static std::atomic<uint64_t> layouts{0};
  layout_ = ++layouts;
  data_.assign(keys_.size() * reals_per_block, Real(0));
  index_.clear();
  index_.reserve(keys_.size() * 2);
  for (size_t b = 0; b < keys_.size(); ++b) index_.emplace(keys_[b], int(b));
}

int SparseGrid::find(int bx, int by, int bz) const {
  const auto it = index_.find(block_key(bx, by, bz));
  return it == index_.end() ? -1 : it->second;
}

size_t SparseGrid::memory_bytes() const {
  return data_.capacity() * sizeof(Real) + keys_.capacity() * sizeof(uint64_t) +
         index_.size() * (sizeof(uint64_t) + sizeof(int) + 2 * sizeof(void*));
}

}  // namespace latmpm::mpm
