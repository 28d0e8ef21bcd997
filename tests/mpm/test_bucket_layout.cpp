// The bucket layout handed between process counts (bucket_layout.hpp): the rows N processes
// write of a checkpoint make the one-process layout, and a process resuming it keeps whole
// buckets.
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

#include "mpm/bucket_layout.hpp"
#include "mpm/bucket_partition.hpp"

using namespace latmpm::mpm;

namespace {
// 600 particles of two bodies scattered over 3×2×2 buckets (cell 0.5: buckets 4 wide),
// sorted as the solver sorts them: the one-process layout.
Particles sorted_particles(ParticleBuckets& buckets) {
  Particles ps;
  ps.resize(600);
  std::mt19937 random(7);
  std::uniform_real_distribution<Real> x(-4, 8), yz(0, 8);
  for (size_t p = 0; p < ps.size(); ++p) {
    ps.position[p] = Vec3(x(random), yz(random), yz(random));
    ps.body[p] = int32_t(p % 3 == 0);
    ps.id[p] = uint32_t(p);
  }
  buckets.sort(ps, 0.5);
  return ps;
}

bool same_tables(const BucketTables& a, const std::vector<Bucket>& buckets, const std::vector<BodyRun>& runs) {
  if (a.buckets.size() != buckets.size() || a.runs.size() != runs.size()) return false;
  for (size_t b = 0; b < buckets.size(); ++b) {
    const Bucket &x = a.buckets[b], &y = buckets[b];
    if (x.coord != y.coord || x.begin != y.begin || x.end != y.end || x.run_begin != y.run_begin || x.run_end != y.run_end)
      return false;
  }
  for (size_t r = 0; r < runs.size(); ++r)
    if (a.runs[r].body != runs[r].body || a.runs[r].begin != runs[r].begin || a.runs[r].end != runs[r].end) return false;
  return true;
}
}  // namespace

TEST_CASE("Buckets split among processes, each writing its rows, give the one-process layout", "[mpm][mpi]") {
  ParticleBuckets sorted;
  const Particles ps = sorted_particles(sorted);
  REQUIRE(sorted.buckets().size() == 12);
  const BucketTables whole{sorted.buckets(), sorted.runs()};

  // Three processes holding buckets by a Morton partition (not contiguous in bucket order).
  std::vector<std::pair<uint64_t, uint64_t>> counts;
  for (const Bucket& b : whole.buckets) counts.emplace_back(morton_key(b.coord), b.end - b.begin);
  std::sort(counts.begin(), counts.end());
  const BucketPartition partition = partition_buckets(counts, 3);
  std::vector<BucketTables> parts;
  std::vector<std::vector<uint32_t>> held_particles;  // each part's particles (their indices in ps), in its order
  std::vector<BucketSize> all;                        // what the processes tell one another
  for (int q = 2; q >= 0; --q) {  // in reverse, so that nothing follows from the parts' order
    BucketTables part = whole;
    std::vector<uint8_t> keep(whole.buckets.size());
    for (size_t b = 0; b < keep.size(); ++b) keep[b] = partition.owner(whole.buckets[b].coord) == q;
    const std::vector<uint8_t> held = select_buckets(part, keep, ps.size());
    std::vector<uint32_t> mine;
    for (uint32_t p = 0; p < ps.size(); ++p)
      if (held[p]) mine.push_back(p);
    REQUIRE(!mine.empty());
    // The part's tables index its own particles: each run of bucket b is that body's particles in it.
    for (const Bucket& b : part.buckets)
      for (uint32_t r = b.run_begin; r < b.run_end; ++r)
        for (uint32_t i = part.runs[r].begin; i < part.runs[r].end; ++i) {
          CHECK(ps.body[mine[i]] == part.runs[r].body);
          CHECK(bucket_of(ps.position[mine[i]], 2.0) == b.coord);
        }
    const auto sizes = bucket_sizes(part.buckets);
    all.insert(all.end(), sizes.begin(), sizes.end());
    parts.push_back(part);
    held_particles.push_back(mine);
  }
  // Each part writes its rows into the one-process tables and particle array.
  std::vector<int64_t> bucket_table(whole.buckets.size() * bucket_row_width, -1), run_table(whole.runs.size() * run_row_width, -1);
  std::vector<int64_t> particle_at(ps.size(), -1);  // which particle of ps each row receives
  for (size_t q = 0; q < parts.size(); ++q) {
    const BucketPlacement placement = place_buckets(all, parts[q].buckets, 0);
    CHECK(placement.buckets == whole.buckets.size());
    CHECK(placement.particles == ps.size());
    CHECK(placement.runs == whole.runs.size());
    const OneProcessRows rows = one_process_rows(parts[q], placement, held_particles[q].size());
    auto scatter = [](const std::vector<int64_t>& values, size_t width, const std::vector<latmpm::RowBlock>& blocks,
                      std::vector<int64_t>& table) {
      size_t at = 0;
      for (const auto& block : blocks)
        for (size_t row = block.first; row < block.first + block.count; ++row)
          for (size_t c = 0; c < width; ++c) table.at(row * width + c) = values.at(at++);
      CHECK(at == values.size());
    };
    scatter(rows.buckets, bucket_row_width, rows.bucket_blocks, bucket_table);
    scatter(rows.runs, run_row_width, rows.run_blocks, run_table);
    std::vector<int64_t> mine(held_particles[q].begin(), held_particles[q].end());
    scatter(mine, 1, rows.particle_blocks, particle_at);
  }
  CHECK(bucket_table == bucket_rows(whole.buckets));
  CHECK(run_table == run_rows(whole.runs));
  // Every particle lands where one process has it.
  bool identity = true;
  for (size_t i = 0; i < ps.size(); ++i) identity = identity && particle_at[i] == int64_t(i);
  CHECK(identity);
}

TEST_CASE("Particles saved before their first sort are one block, written by one process", "[mpm][mpi]") {
  const BucketTables none;
  const BucketPlacement placement = place_buckets({}, none.buckets, 40);
  CHECK(placement.particles == 40);
  const OneProcessRows rows = one_process_rows(none, placement, 40);
  REQUIRE(rows.particle_blocks.size() == 1);
  CHECK(rows.particle_blocks[0].first == 0);
  CHECK(rows.particle_blocks[0].count == 40);
  BucketPlacement other = placement;
  other.writes = false;  // every process holds every particle: rank 0 alone writes them
  CHECK(one_process_rows(none, other, 40).particle_blocks.empty());
}

TEST_CASE("Bucket and run tables survive their int64 rows", "[mpm][mpi]") {
  ParticleBuckets sorted;
  sorted_particles(sorted);
  const BucketTables back{buckets_from_rows(bucket_rows(sorted.buckets())), runs_from_rows(run_rows(sorted.runs()))};
  CHECK(same_tables(back, sorted.buckets(), sorted.runs()));
}

TEST_CASE("Keeping no bucket keeps no particle, keeping all keeps the layout", "[mpm][mpi]") {
  ParticleBuckets sorted;
  const Particles ps = sorted_particles(sorted);
  BucketTables none{sorted.buckets(), sorted.runs()};
  const auto held_none = select_buckets(none, std::vector<uint8_t>(sorted.buckets().size(), 0), ps.size());
  CHECK(std::count(held_none.begin(), held_none.end(), 1) == 0);
  CHECK(none.buckets.empty());
  CHECK(none.runs.empty());
  BucketTables all{sorted.buckets(), sorted.runs()};
  const auto held_all = select_buckets(all, std::vector<uint8_t>(sorted.buckets().size(), 1), ps.size());
  CHECK(std::count(held_all.begin(), held_all.end(), 1) == int(ps.size()));
  CHECK(same_tables(all, sorted.buckets(), sorted.runs()));
}
