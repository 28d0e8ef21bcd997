#include "run_output/checkpoint_checks.hpp"

#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "core/checked_read.hpp"
#include "core/errors.hpp"
#include "core/hdf5_file.hpp"
#include "mpm/checkpoint_io.hpp"
#include "mpm/particle_fields.hpp"
#include "mpm/simulation.hpp"

namespace latmpm {
namespace {

constexpr double big = std::numeric_limits<double>::max();

// Ids are a permutation of 0..n-1: the solver orders particles by them.
void check_permutation(const Hdf5File& f, const std::string& dataset, const std::vector<int64_t>& ids) {
  std::vector<char> seen(ids.size(), 0);
  for (int64_t id : ids) {
    if (seen[size_t(id)]) throw InputError(f.path(), dataset, "id " + std::to_string(id) + " appears twice");
    seen[size_t(id)] = 1;
  }
}

// [begin, end) ranges in column `begin_column` of a table: begin <= end, each continuing the
// previous one, from 0 to `limit`. An empty table passes: a run stopped before its first step
// has not sorted its particles into buckets yet.
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

// A one-value dataset (the checkpoint's scalars).
double scalar(const Hdf5File& f, const std::string& dataset, ValueRange range = {}) {
  return read_checked_doubles(f, dataset, {1}, range)[0];
}

}  // namespace

void check_checkpoint(const Hdf5File& f, const mpm::Simulation& sim) {
  const std::string g = "/state";
  const mpm::CheckpointReader format_checked(f, g);  // refuses another format version first
  const size_t n = sim.particles().size(), nb = sim.bodies().size(), nr = sim.rigid_bodies().size();
  const int64_t last_body = int64_t(nb) - 1;

  // Particles: every field of the registry, one row each, finite; indices within their tables.
  const std::string p = g + "/particles/";
  mpm::for_each_particle_field(sim.particles(), [&](const mpm::ParticleField& field, const auto& values, const auto&) {
    using T = typename std::decay_t<decltype(values)>::value_type;
    const std::string name = field.name, dataset = p + name;
    if (field.optional && values.empty()) return;
    if (!f.exists(dataset)) return;  // mpm's reader names a missing field with its reason
    if constexpr (std::is_integral_v<T>) {
      if (name == "body") read_checked_integers(f, dataset, {n}, 0, last_body);
      if (name == "id") check_permutation(f, dataset, read_checked_integers(f, dataset, {n}, 0, int64_t(n) - 1));
      if (name == "flags") read_checked_integers(f, dataset, {n}, 0, 255);
      if (name == "contact_body") read_checked_integers(f, dataset, {n}, -1, int64_t(nr) - 1);
    } else {
      constexpr size_t components = size_t(mpm::CheckpointCodec<T>::components);
      const std::vector<size_t> shape = components == 1 ? std::vector<size_t>{n} : std::vector<size_t>{n, components};
      const bool non_negative = name == "mass" || name == "volume0" || name == "half_size0";
      read_checked_doubles(f, dataset, shape, non_negative ? ValueRange{0, big} : ValueRange{});
    }
  });

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
  read_checked_integers(f, g + "/buckets/needs_sort", {1}, 0, 1);

  // Solver: step, time and time steps non-negative, every scalar finite, per-body rows.
  const int64_t step = read_checked_integers(f, g + "/solver/step", {1}, 0, std::numeric_limits<int64_t>::max())[0];
  for (const char* name : {"time", "dt", "stable_dt"}) scalar(f, g + "/solver/" + name, {0, big});
  for (const char* name : {"kinetic_energy", "strain_energy", "plastic_dissipation", "external_work", "max_speed",
                           "constraint_work", "gravity_work", "rigid_energy", "contact_energy", "friction_dissipation", "energy_error", "carried_max_speed",
                           "carried_max_wave_speed", "initial_energy", "initial_rigid_energy", "driven_rigid_work"})
    if (f.exists(g + "/solver/" + name)) scalar(f, g + "/solver/" + name);
  for (const char* name : {"/solver/body_displacement", "/solver/reaction", "/solver/initial_centre"})
    read_checked_doubles(f, g + name, {nb, 3});
  // Boundaries (boundaries/<name>/): each one's reader checks its rows' shapes and that every
  // value is finite (mpm/checkpoint_io.hpp), before anything is changed.

  // Outputs: the snapshots written so far.
  const size_t frames = read_checked_strings(f, "/output/frame_files").size();
  read_checked_doubles(f, "/output/frame_times", {frames}, {0, big});
  read_checked_integers(f, "/output/frame_steps", {frames}, 0, step);
  read_checked_integers(f, "/output/frame_points", {frames}, 0, int64_t(n));
  read_checked_double_attribute(f, "/output", "wall_seconds", {0, big});
}

}  // namespace latmpm
