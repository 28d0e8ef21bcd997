// Particles in bucket layout (particle_buckets.hpp) handed between process counts: how the
// MPI domain writes a checkpoint of N processes in the one-process layout and resumes it on
// M (docs/cluster.md, "Checkpoints"). Because ParticleBuckets::sort orders particles by a
// total key (bucket, body, cell, id), a bucket holds the same particles in the same order
// on whichever process holds it; the one-process layout is every process's buckets in
// bucket order. No MPI here: pure functions of the layout, tested in every build.
#pragma once
#include <cstdint>
#include <vector>

#include "mpm/particle_buckets.hpp"
#include "mpm/particles.hpp"

namespace latmpm::mpm {

// The buckets and runs that index a particle array (contiguous ranges, as ParticleBuckets
// keeps them; boxes are not carried).
struct BucketTables {
  std::vector<Bucket> buckets;
  std::vector<BodyRun> runs;
};

// Particles with their tables: a process's part, or every process's gathered.
struct BucketedParticles {
  Particles particles;
  BucketTables tables;
};

// The one-process layout of several parts (each part's buckets and runs indexing its own
// particles and runs from 0; its particles following the previous part's in one array):
// the buckets in the order one process keeps them (bucket_order_key), and `order`, the
// concatenated particles' indices in the new order (Particles::permute's argument).
struct MergedLayout {
  BucketTables tables;
  std::vector<uint32_t> order;
};
MergedLayout merge_bucket_layouts(const std::vector<BucketTables>& parts, const std::vector<size_t>& particle_counts);

// Keeps the buckets whose keep[b] is set, with their runs, re-indexed from 0; returns which
// of the `particles` particles they hold (keep, in their order, for the layout to match).
std::vector<uint8_t> select_buckets(BucketTables& tables, const std::vector<uint8_t>& keep, size_t particles);

// Buckets and runs as int64 rows (the checkpoint's tables, and what processes send):
// bucket: coord x y z, begin, end, run_begin, run_end; run: body, begin, end.
inline constexpr size_t bucket_row_width = 7, run_row_width = 3;
std::vector<int64_t> bucket_rows(const std::vector<Bucket>& buckets);
std::vector<int64_t> run_rows(const std::vector<BodyRun>& runs);
std::vector<Bucket> buckets_from_rows(const std::vector<int64_t>& rows);
std::vector<BodyRun> runs_from_rows(const std::vector<int64_t>& rows);

}  // namespace latmpm::mpm
