#include "run_output/checkpoint_checks.hpp"

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "core/checked_read.hpp"
#include "core/errors.hpp"
#include "core/hdf5_file.hpp"

namespace latmpm {
namespace {

constexpr double big = std::numeric_limits<double>::max();

// Ids are a permutation of 0..n-1: the solver orders particles by them.
void check_permutation(const Hdf5File& f, const std::string& dataset, const std::vector<int64_t>& ids) {
  std::vector<char> seen(ids.size(), 0);
  for (size_t i = 0; i < ids.size(); ++i) {
    if (seen[size_t(ids[i])]) throw InputError(f.path(), dataset, "id " + std::to_string(ids[i]) + " appears twice");
    seen[size_t(ids[i])] = 1;
  }
}

// [begin, end) ranges of a table's rows that must lie in [0, limit], begin <= end, and
// follow each other without gap or overlap from 0 to `limit`. An empty table passes: a run
// stopped before its first step has not sorted its particles into buckets yet.
void check_ranges(const Hdf5File& f, const std::string& dataset, const std::vector<int64_t>& table, size_t columns,
                  size_t begin_column, int64_t limit, const std::string& what) {
  int64_t expected = 0;
  for (size_t row = 0; row < table.size() / columns; ++row) {
    const int64_t begin = table[row * columns + begin_column], end = table[row * columns + begin_column + 1];
    if (begin != expected || end < begin || end > limit)
      throw InputError(f.path(), dataset, "row " + std::to_string(row) + ": " + what + " range [" +
                                              std::to_string(begin) + ", " + std::to_string(end) +
                                              ") does not continue the previous one within [0, " +
                                              std::to_string(limit) + ")");
    expected = end;
  }
  if (!table.empty() && expected != limit)
    throw InputError(f.path(), dataset, "the " + what + " ranges end at " + std::to_string(expected) + ", not at " +
                                            std::to_string(limit));
}

}  // namespace

void check_checkpoint(const Hdf5File& f, const CheckpointShape& s) {
  const std::string g = "/state";
  const size_t n = s.particles, nb = s.bodies, nr = s.rigid_bodies;
  const int64_t last_body = int64_t(nb) - 1;

  // Particles: one row each.
  read_checked_doubles(f, g + "/particles/position", {n, 3});
  read_checked_doubles(f, g + "/particles/velocity", {n, 3});
  read_checked_doubles(f, g + "/particles/mass", {n}, {0, big});
  read_checked_doubles(f, g + "/particles/volume0", {n}, {0, big});
  read_checked_doubles(f, g + "/particles/deformation", {n, 9});
  read_checked_doubles(f, g + "/particles/stress", {n, 6});
  read_checked_doubles(f, g + "/particles/half_size0", {n, 3}, {0, big});
  read_checked_integers(f, g + "/particles/body", {n}, 0, last_body);
  check_permutation(f, g + "/particles/id", read_checked_integers(f, g + "/particles/id", {n}, 0, int64_t(n) - 1));
  read_checked_integers(f, g + "/particles/flags", {n}, 0, 255);
  if (f.exists(g + "/particles/contact_body")) {
    read_checked_integers(f, g + "/particles/contact_body", {n}, -1, int64_t(nr) - 1);
    read_checked_doubles(f, g + "/particles/contact_anchor", {n, 3});
  }

  // Buckets and runs: contiguous particle ranges; each bucket's runs a contiguous range of runs.
  const auto runs = read_checked_integers(f, g + "/buckets/runs", {any_extent, 3}, 0, int64_t(n));
  for (size_t r = 0; r < runs.size() / 3; ++r)
    if (runs[3 * r] > last_body)
      throw InputError(f.path(), g + "/buckets/runs", "row " + std::to_string(r) + ": body " +
                                                          std::to_string(runs[3 * r]) + " of " + std::to_string(nb));
  check_ranges(f, g + "/buckets/runs", runs, 3, 1, int64_t(n), "particle");
  const auto buckets = read_checked_integers(f, g + "/buckets/buckets", {any_extent, 7},
                                             std::numeric_limits<int32_t>::min() / 8,
                                             std::numeric_limits<int32_t>::max() / 8);
  check_ranges(f, g + "/buckets/buckets", buckets, 7, 3, int64_t(n), "particle");
  check_ranges(f, g + "/buckets/buckets", buckets, 7, 5, int64_t(runs.size() / 3), "run");
  read_checked_integer_attribute(f, g + "/buckets/buckets", "needs_sort", 0, 1);

  // Solver: per body, the scalars (step, time and time steps non-negative), rigid bodies.
  read_checked_doubles(f, g + "/solver/body_displacement", {nb, 3});
  read_checked_doubles(f, g + "/solver/reaction", {nb, 3});
  read_checked_doubles(f, g + "/solver/initial_centre", {nb, 3});
  const auto scalars = read_checked_doubles(f, g + "/solver/scalars", {18});
  const char* const names[] = {"step", "time", "dt", "stable dt"};
  for (int i = 0; i < 4; ++i)
    if (scalars[size_t(i)] < 0 || (i == 0 && scalars[0] > 9.0e15))
      throw InputError(f.path(), g + "/solver/scalars", std::string(names[i]) + " is " + std::to_string(scalars[i]));
  for (const char* dataset : {"/rigid/displacement", "/rigid/velocity", "/rigid/reaction"})
    read_checked_doubles(f, g + dataset, {nr, 3});
  read_checked_doubles(f, g + "/rigid/work", {nr});

  // Outputs: the snapshots written so far.
  const size_t frames = read_checked_strings(f, "/output/frame_files").size();
  read_checked_doubles(f, "/output/frame_times", {frames}, {0, big});
  read_checked_integers(f, "/output/frame_steps", {frames}, 0, int64_t(scalars[0]));
  read_checked_integers(f, "/output/frame_points", {frames}, 0, int64_t(n));
  read_checked_double_attribute(f, "/output", "wall_seconds", {0, big});
}

}  // namespace latmpm
