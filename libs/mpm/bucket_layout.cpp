#include "mpm/bucket_layout.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "mpm/bucket_partition.hpp"

namespace latmpm::mpm {

MergedLayout merge_bucket_layouts(const std::vector<BucketTables>& parts, const std::vector<size_t>& particle_counts) {
  if (parts.size() != particle_counts.size()) throw std::logic_error("merge_bucket_layouts: one count per part");
  // Every bucket as (part, index), in bucket order; a bucket is held by one part.
  std::vector<std::pair<uint32_t, uint32_t>> all;
  std::vector<size_t> first_particle(parts.size(), 0);
  for (size_t q = 0; q < parts.size(); ++q) {
    if (q > 0) first_particle[q] = first_particle[q - 1] + particle_counts[q - 1];
    for (uint32_t b = 0; b < parts[q].buckets.size(); ++b) all.emplace_back(uint32_t(q), b);
  }
  auto key = [&](const std::pair<uint32_t, uint32_t>& item) { return bucket_order_key(parts[item.first].buckets[item.second]); };
  std::sort(all.begin(), all.end(), [&](const auto& a, const auto& b) { return key(a) < key(b); });

  MergedLayout out;
  out.order.reserve(first_particle.empty() ? 0 : first_particle.back() + particle_counts.back());
  for (const auto& [q, b] : all) {
    const Bucket& from = parts[q].buckets[b];
    Bucket to = from;
    to.begin = uint32_t(out.order.size());
    to.run_begin = uint32_t(out.tables.runs.size());
    for (uint32_t r = from.run_begin; r < from.run_end; ++r) {
      const BodyRun& run = parts[q].runs[r];
      const uint32_t begin = uint32_t(out.order.size());
      for (uint32_t p = run.begin; p < run.end; ++p) out.order.push_back(uint32_t(first_particle[q] + p));
      out.tables.runs.push_back({run.body, begin, uint32_t(out.order.size())});
    }
    to.end = uint32_t(out.order.size());
    to.run_end = uint32_t(out.tables.runs.size());
    out.tables.buckets.push_back(to);
  }
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
