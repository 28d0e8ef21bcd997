#include "mpm/bucket_layout.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "mpm/bucket_partition.hpp"

namespace latmpm::mpm {

std::vector<BucketSize> bucket_sizes(const std::vector<Bucket>& buckets) {
  std::vector<BucketSize> sizes;
  sizes.reserve(buckets.size());
  for (const Bucket& b : buckets) sizes.push_back({bucket_order_key(b), b.end - b.begin, b.run_end - b.run_begin});
  return sizes;
}

BucketPlacement place_buckets(std::vector<BucketSize> all, const std::vector<Bucket>& mine, uint64_t particles) {
  std::sort(all.begin(), all.end(), [](const BucketSize& a, const BucketSize& b) { return a.key < b.key; });
  BucketPlacement out;
  out.buckets = all.size();
  out.particles = all.empty() ? particles : 0;
  // Prefix sums in bucket order; this process's buckets are among them, in the same order.
  size_t at = 0;
  for (const Bucket& b : mine) {
    const uint64_t key = bucket_order_key(b);
    for (; at < all.size() && all[at].key < key; ++at) out.particles += all[at].particles, out.runs += all[at].runs;
    if (at == all.size() || all[at].key != key) throw std::logic_error("place_buckets: a bucket of this process is not among all");
    out.row.push_back(at), out.first_particle.push_back(out.particles), out.first_run.push_back(out.runs);
  }
  for (; at < all.size(); ++at) out.particles += all[at].particles, out.runs += all[at].runs;
  return out;
}

namespace {
// Appends rows [first, first + count) to `blocks`, joined to the last block where they continue it.
void add_block(std::vector<RowBlock>& blocks, uint64_t first, uint64_t count) {
  if (count == 0) return;
  if (!blocks.empty() && blocks.back().first + blocks.back().count == first)
    blocks.back().count += count;
  else
    blocks.push_back({size_t(first), size_t(count)});
}
}  // namespace

OneProcessRows one_process_rows(const BucketTables& mine, const BucketPlacement& placement, size_t particles) {
  OneProcessRows out;
  if (!placement.writes) return out;
  if (mine.buckets.empty()) {  // before the first sort: the particles as they are
    add_block(out.particle_blocks, 0, particles);
    return out;
  }
  // This process's buckets and runs moved to their one-process indices, written as
  // bucket_rows and run_rows write a one-process table.
  std::vector<Bucket> placed;
  std::vector<BodyRun> placed_runs;
  placed.reserve(mine.buckets.size());
  uint32_t next = 0;  // the buckets' particles follow one another here (the sort's layout)
  for (size_t b = 0; b < mine.buckets.size(); ++b) {
    const Bucket& bucket = mine.buckets[b];
    if (bucket.begin != next) throw std::logic_error("one_process_rows: the buckets do not hold the particles in order");
    next = bucket.end;
    const uint32_t first = uint32_t(placement.first_particle[b]), first_run = uint32_t(placement.first_run[b]);
    Bucket moved = bucket;
    moved.begin = first, moved.end = first + (bucket.end - bucket.begin);
    moved.run_begin = first_run, moved.run_end = first_run + (bucket.run_end - bucket.run_begin);
    placed.push_back(moved);
    for (uint32_t r = bucket.run_begin; r < bucket.run_end; ++r) {
      BodyRun run = mine.runs[r];
      run.begin = run.begin - bucket.begin + first, run.end = run.end - bucket.begin + first;
      placed_runs.push_back(run);
    }
    add_block(out.bucket_blocks, placement.row[b], 1);
    add_block(out.run_blocks, placement.first_run[b], bucket.run_end - bucket.run_begin);
    add_block(out.particle_blocks, placement.first_particle[b], bucket.end - bucket.begin);
  }
  if (next != particles) throw std::logic_error("one_process_rows: particles outside the buckets");
  out.buckets = bucket_rows(placed);
  out.runs = run_rows(placed_runs);
  return out;
}

std::vector<uint8_t> select_buckets(BucketTables& tables, const std::vector<uint8_t>& keep, size_t particles) {
  std::vector<uint8_t> held(particles, 0);
  std::vector<Bucket> buckets;
  std::vector<BodyRun> runs;
  uint32_t next_particle = 0;
  for (size_t b = 0; b < tables.buckets.size(); ++b) {
    if (!keep[b]) continue;
    Bucket bucket = tables.buckets[b];
    const int64_t shift = int64_t(next_particle) - int64_t(bucket.begin);  // its particles move down by the dropped ones
    std::fill(held.begin() + bucket.begin, held.begin() + bucket.end, uint8_t(1));
    const uint32_t first_run = uint32_t(runs.size());
    for (uint32_t r = bucket.run_begin; r < bucket.run_end; ++r) {
      BodyRun run = tables.runs[r];
      run.begin = uint32_t(int64_t(run.begin) + shift), run.end = uint32_t(int64_t(run.end) + shift);
      runs.push_back(run);
    }
    next_particle += bucket.end - bucket.begin;
    bucket.begin = uint32_t(int64_t(bucket.begin) + shift), bucket.end = next_particle;
    bucket.run_begin = first_run, bucket.run_end = uint32_t(runs.size());
    buckets.push_back(bucket);
  }
  tables.buckets = std::move(buckets);
  tables.runs = std::move(runs);
  return held;
}

std::vector<int64_t> bucket_rows(const std::vector<Bucket>& buckets) {
  std::vector<int64_t> rows;
  rows.reserve(buckets.size() * bucket_row_width);
  for (const auto& b : buckets) rows.insert(rows.end(), {b.coord[0], b.coord[1], b.coord[2], b.begin, b.end, b.run_begin, b.run_end});
  return rows;
}

std::vector<int64_t> run_rows(const std::vector<BodyRun>& runs) {
  std::vector<int64_t> rows;
  rows.reserve(runs.size() * run_row_width);
  for (const auto& r : runs) rows.insert(rows.end(), {r.body, r.begin, r.end});
  return rows;
}

std::vector<Bucket> buckets_from_rows(const std::vector<int64_t>& rows) {
  std::vector<Bucket> buckets(rows.size() / bucket_row_width);
  for (size_t i = 0; i < buckets.size(); ++i) {
    const int64_t* x = &rows[bucket_row_width * i];
    buckets[i].coord = {int(x[0]), int(x[1]), int(x[2])};
    buckets[i].begin = uint32_t(x[3]), buckets[i].end = uint32_t(x[4]);
    buckets[i].run_begin = uint32_t(x[5]), buckets[i].run_end = uint32_t(x[6]);
    buckets[i].box_lo = buckets[i].box_hi = {0, 0, 0};
  }
  return buckets;
}

std::vector<BodyRun> runs_from_rows(const std::vector<int64_t>& rows) {
  std::vector<BodyRun> runs(rows.size() / run_row_width);
  for (size_t i = 0; i < runs.size(); ++i)
    runs[i] = {int32_t(rows[run_row_width * i]), uint32_t(rows[run_row_width * i + 1]), uint32_t(rows[run_row_width * i + 2])};
  return runs;
}

}  // namespace latmpm::mpm
