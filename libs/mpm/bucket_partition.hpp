// How a run spread over several processes divides the material (the MPI issue): whole
// particle buckets (8×8×8 cells, particle_buckets.hpp) are the unit, ordered along a Morton
// (Z-order) space-filling curve of their coordinates and cut into contiguous pieces of
// about equal particle count. A bucket is the unit because the one-process step sums per
// bucket (its P2G buffer, its tallies): a process that holds whole buckets computes them
// bit for bit as one process does (docs/cluster.md). No MPI here: the partition is a pure
// function of the buckets' particle counts, the same on every process.
#pragma once
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "mpm/real.hpp"

namespace latmpm::mpm {

struct Bucket;

// Position of bucket `bucket` (bucket coordinates, within ±2^20 per axis) on the Morton
// curve: the bits of x, y and z interleaved, x most significant.
uint64_t morton_key(const std::array<int, 3>& bucket);

// The bucket holding x (cell size h): what ParticleBuckets::sort files the particle under.
std::array<int, 3> bucket_of(const Vec3& x, Real inv_h);

// A key that sorts buckets in the order one process keeps them (x-major, like
// ParticleBuckets::sort): the order in which per-bucket partial sums are added
// (Domain::sum_in_order), whichever process holds each bucket.
uint64_t bucket_order_key(const Bucket& bucket);
std::vector<uint64_t> bucket_order_keys(const std::vector<Bucket>& buckets);

// Contiguous ranges of the Morton curve, one per process: process r owns the buckets whose
// key k has cuts[r−1] ≤ k < cuts[r] (cuts[−1] = 0, cuts[parts−1] = ∞). Every bucket in
// space has an owner, occupied or not, so a particle moving into an empty bucket has one.
struct BucketPartition {
  std::vector<uint64_t> cuts;  // parts − 1 ascending keys
  int parts() const { return int(cuts.size()) + 1; }
  int owner(uint64_t key) const;
  int owner(const std::array<int, 3>& bucket) const { return owner(morton_key(bucket)); }
};

// Cuts the buckets, given as (Morton key, particle count) sorted by key with unique keys,
// into `parts` ranges whose particle counts are as equal as whole buckets allow (each range
// ends at the first bucket where the running count reaches its share).
BucketPartition partition_buckets(const std::vector<std::pair<uint64_t, uint64_t>>& counts, int parts);

}  // namespace latmpm::mpm
