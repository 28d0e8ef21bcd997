#include "mpm/particle_buckets.hpp"

#include <algorithm>
#include <numeric>

#include "mpm/sparse_grid.hpp"

namespace latmpm::mpm {

namespace {
// Sort key: bucket (3 × 14 bits), body (13 bits), cell inside the bucket (9 bits).
// Bucket coordinates are within ±2^13 since cells are checked against the grid's range
// (±2^22 cells / 8 ... the grid's block range is the tighter limit, see simulation.cpp).
constexpr int bucket_bits = 14;
constexpr int bucket_offset = 1 << (bucket_bits - 1);

uint64_t sort_key(const std::array<int, 3>& cell, int body) {
  uint64_t key = 0;
  for (int a = 0; a < 3; ++a)
    key = (key << bucket_bits) | uint64_t(floor_div(cell[a], ParticleBuckets::cells) + bucket_offset);
  key = (key << 13) | uint64_t(body);
  uint64_t local = 0;
  for (int a = 0; a < 3; ++a) {
    const int c = cell[a] - ParticleBuckets::cells * floor_div(cell[a], ParticleBuckets::cells);
    local = (local << 3) | uint64_t(c);
  }
  return (key << 9) | local;
}

std::array<int, 3> bucket_of_key(uint64_t key) {
  key >>= 9 + 13;
  std::array<int, 3> c;
  for (int a = 2; a >= 0; --a) {
    c[a] = int(key & ((uint64_t(1) << bucket_bits) - 1)) - bucket_offset;
    key >>= bucket_bits;
  }
  return c;
}
}  // namespace

void ParticleBuckets::restore(std::vector<Bucket> buckets, std::vector<BodyRun> runs) {
  buckets_ = std::move(buckets);
  runs_ = std::move(runs);
  for (auto& c : colours_) c.clear();
  for (size_t i = 0; i < buckets_.size(); ++i) {
    const auto& b = buckets_[i];
    colours_[(b.coord[0] & 1) * 4 + (b.coord[1] & 1) * 2 + (b.coord[2] & 1)].push_back(uint32_t(i));
  }
}

void ParticleBuckets::sort(Particles& particles, Real cell_size) {
  const size_t n = particles.size();
  const Real inv_h = 1 / cell_size;
  keys_.resize(n);
  // With grid contact a run is one (body, field): body · 32 + field in the key's body bits.
  const bool fields = !particles.contact_field.empty();
  auto group = [&](size_t p) { return fields ? particles.body[p] * 32 + particles.contact_field[p] : particles.body[p]; };
  for (size_t p = 0; p < n; ++p) keys_[p] = sort_key(cell_of(particles.position[p], inv_h), group(p));
  order_.resize(n);
  std::iota(order_.begin(), order_.end(), 0u);
  std::sort(order_.begin(), order_.end(), [&](uint32_t a, uint32_t b) {
    return keys_[a] != keys_[b] ? keys_[a] < keys_[b] : particles.id[a] < particles.id[b];
  });
  bool sorted = true;
  for (size_t i = 0; i < n && sorted; ++i) sorted = order_[i] == i;
  if (!sorted) {
    particles.permute(order_);
    std::vector<uint64_t> permuted(n);
    for (size_t i = 0; i < n; ++i) permuted[i] = keys_[order_[i]];
    keys_.swap(permuted);
  }

  buckets_.clear();
  runs_.clear();
  for (auto& c : colours_) c.clear();
  constexpr uint64_t bucket_shift = 9 + 13;
  for (size_t p = 0; p < n;) {
    Bucket b;
    b.coord = bucket_of_key(keys_[p]);
    b.begin = uint32_t(p);
    b.run_begin = uint32_t(runs_.size());
    const uint64_t bucket_key = keys_[p] >> bucket_shift;
    while (p < n && (keys_[p] >> bucket_shift) == bucket_key) {
      BodyRun run{particles.body[p], uint32_t(p), 0};
      const int run_group = group(p);
      while (p < n && (keys_[p] >> bucket_shift) == bucket_key && group(p) == run_group) ++p;
      run.end = uint32_t(p);
      runs_.push_back(run);
    }
    b.end = uint32_t(p);
    b.run_end = uint32_t(runs_.size());
    b.box_lo = b.box_hi = {0, 0, 0};
    const int colour = (b.coord[0] & 1) * 4 + (b.coord[1] & 1) * 2 + (b.coord[2] & 1);
    colours_[colour].push_back(uint32_t(buckets_.size()));
    buckets_.push_back(b);
  }
}

}  // namespace latmpm::mpm
