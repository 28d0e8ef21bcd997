// The MPI domain's partition of particle buckets (bucket_partition.hpp): a Morton curve cut
// into ranges of about equal particle count, an owner for every bucket in space.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>

#include "mpm/bucket_partition.hpp"
#include "mpm/particle_buckets.hpp"

using namespace latmpm::mpm;

TEST_CASE("Morton keys interleave the bucket coordinates and keep neighbours in one octant together", "[mpm][mpi]") {
  // Within the octant of 2×2×2 buckets starting at an even corner, keys are consecutive
  // and ordered x (most significant), y, z.
  const uint64_t base = morton_key({4, -6, 10});
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 2; ++k) CHECK(morton_key({4 + i, -6 + j, 10 + k}) == base + uint64_t(4 * i + 2 * j + k));
  // Distinct buckets, distinct keys; the key orders octants before their insides.
  CHECK(morton_key({0, 0, 0}) != morton_key({-1, 0, 0}));
  CHECK(morton_key({1, 1, 1}) < morton_key({2, 0, 0}));
}

TEST_CASE("A particle's bucket is the one the bucket sort files it under", "[mpm][mpi]") {
  const Real h = 0.5;
  CHECK(bucket_of(Vec3(0.1, 3.99, -0.01), 1 / h) == std::array<int, 3>{0, 0, -1});
  CHECK(bucket_of(Vec3(4.0, -4.0, -4.01), 1 / h) == std::array<int, 3>{1, -1, -2});
}

TEST_CASE("The partition cuts the curve into ranges of about equal particle count", "[mpm][mpi]") {
  // 64 buckets on a 4×4×4 block, uneven counts.
  std::map<uint64_t, uint64_t> buckets;
  uint64_t total = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k) {
        const uint64_t count = uint64_t(1 + (i * 7 + j * 3 + k) % 5) * 100;
        buckets[morton_key({i, j, k})] = count;
        total += count;
      }
  const std::vector<std::pair<uint64_t, uint64_t>> counts(buckets.begin(), buckets.end());
  for (int parts : {1, 2, 3, 4, 7}) {
    const BucketPartition partition = partition_buckets(counts, parts);
    REQUIRE(partition.parts() == parts);
    CHECK(std::is_sorted(partition.cuts.begin(), partition.cuts.end()));
    // Owners rise along the curve (contiguous ranges), and each range is within one
    // bucket (at most 500 particles, and the rounding of the share) of its share.
    std::vector<uint64_t> held(size_t(parts), 0);
    int last = 0;
    for (const auto& [key, count] : counts) {
      const int owner = partition.owner(key);
      CHECK(owner >= last);
      last = owner;
      held[size_t(owner)] += count;
    }
    for (uint64_t h : held) CHECK(std::abs(double(h) - double(total) / parts) <= 501);
  }
}

TEST_CASE("Every bucket in space has an owner, occupied or not", "[mpm][mpi]") {
  const BucketPartition partition = partition_buckets({{morton_key({0, 0, 0}), 10}, {morton_key({5, 5, 5}), 10}}, 2);
  CHECK(partition.owner({0, 0, 0}) == 0);
  CHECK(partition.owner({5, 5, 5}) == 1);
  for (const std::array<int, 3> far : {std::array<int, 3>{-1000, 3, 9}, std::array<int, 3>{1000, -1000, 1000}}) {
    const int owner = partition.owner(far);
    CHECK((owner == 0 || owner == 1));
  }
  // More processes than buckets: the extra ranges are empty, not an error.
  const BucketPartition wide = partition_buckets({{morton_key({0, 0, 0}), 10}}, 4);
  CHECK(wide.parts() == 4);
  CHECK(wide.owner({0, 0, 0}) == 0);
}
