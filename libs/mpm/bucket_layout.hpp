// Particles in bucket layout (particle_buckets.hpp) handed between process counts: how the
// processes of an MPI run write a checkpoint in the one-process layout, each its own rows,
// and resume it on M (docs/cluster.md, "Checkpoints"). Because ParticleBuckets::sort orders particles by a
// total key (bucket, body, cell, id), a bucket holds the same particles in the same order
// on whichever process holds it; the one-process layout is every process's buckets in
// bucket order. No MPI here: pure functions of the layout, tested in every build.
#pragma once
#include <cstdint>
#include <vector>

#include "core/hdf5_file.hpp"  // RowBlock
#include "mpm/particle_buckets.hpp"
#include "mpm/particles.hpp"

namespace latmpm::mpm {

// The buckets and runs that index a particle array (contiguous ranges, as ParticleBuckets
// keeps them; boxes are not carried).
struct BucketTables {
  std::vector<Bucket> buckets;
  std::vector<BodyRun> runs;
};

// A bucket as processes tell one another about theirs: its key in bucket order
// (bucket_order_key) and the particles and runs it holds.
struct BucketSize {
  uint64_t key = 0, particles = 0, runs = 0;
};
std::vector<BucketSize> bucket_sizes(const std::vector<Bucket>& buckets);

// Where a process's buckets go in the one-process layout (every process's buckets in bucket
// order): of each of its buckets, its row in the one-process bucket table and the one-process
// index of its first particle and first run; and the tables' totals. `writes`: this process
// writes its rows (false for all but rank 0 while every process holds every particle).
struct BucketPlacement {
  std::vector<uint64_t> row, first_particle, first_run;
  uint64_t buckets = 0, particles = 0, runs = 0;
  bool writes = true;
};
// From every process's bucket sizes (any order, each key once) and this process's buckets
// (in bucket order, among them). `particles`: the total when there are no buckets (a run
// saved before its first sort, every process holding every particle).
BucketPlacement place_buckets(std::vector<BucketSize> all, const std::vector<Bucket>& mine, uint64_t particles);

// This process's part of the one-process checkpoint's tables and particle arrays: its bucket
// and run rows with one-process indices (bucket_rows' and run_rows' columns), and the row
// blocks they and its `particles` particles (in their order here) fill. So N processes
// write the file one process writes, each its own rows (docs/cluster.md, "Checkpoints").
struct OneProcessRows {
  std::vector<int64_t> buckets, runs;
  std::vector<RowBlock> bucket_blocks, run_blocks, particle_blocks;
};
OneProcessRows one_process_rows(const BucketTables& mine, const BucketPlacement& placement, size_t particles);

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
