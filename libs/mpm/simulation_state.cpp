// Saving and restoring a Simulation's state for checkpoints, as named datasets through
// checkpoint_io.hpp. The particles are stored in their internal (bucket-sorted) order
// together with the buckets and runs, so a restored run scatters and gathers in exactly the
// order the uninterrupted one would: results agree bit for bit (the thread count does not
// matter, step_stages.hpp). Every particle field comes from the registry
// (particle_fields.hpp).
#include <limits>
#include <type_traits>

#include "core/errors.hpp"
#include "core/hdf5_file.hpp"
#include "mpm/bucket_layout.hpp"
#include "mpm/bucket_partition.hpp"
#include "mpm/checkpoint_io.hpp"
#include "mpm/particle_fields.hpp"
#include "mpm/simulation.hpp"
#include "mpm/step_stages.hpp"

namespace latmpm::mpm {

namespace {
constexpr ValueRange non_negative{0, std::numeric_limits<double>::max()};

// The step's diagnostics and the carried solver scalars, by name (both directions), with the
// range a checkpoint's value must lie in (finite for all).
template <class D, class C, class Visit>
void for_each_solver_scalar(D& d, C& carried, Visit&& visit) {
  visit("time", d.time, non_negative);
  visit("dt", d.dt, non_negative);
  visit("stable_dt", d.stable_dt, non_negative);
  visit("kinetic_energy", d.kinetic_energy, ValueRange{});
  visit("strain_energy", d.strain_energy, ValueRange{});
  visit("plastic_dissipation", d.plastic_dissipation, ValueRange{});
  visit("external_work", d.external_work, ValueRange{});
  visit("max_speed", d.max_speed, ValueRange{});
  visit("constraint_work", d.constraint_work, ValueRange{});
  visit("gravity_work", d.gravity_work, ValueRange{});
  visit("rigid_energy", d.rigid_energy, ValueRange{});
  visit("contact_energy", d.contact_energy, ValueRange{});
  visit("friction_dissipation", d.friction_dissipation, ValueRange{});
  visit("blend_dissipation", d.blend_dissipation, ValueRange{});
  visit("transfer_dissipation", d.transfer_dissipation, ValueRange{});
  visit("grid_contact_dissipation", d.grid_contact_dissipation, ValueRange{});
  visit("energy_error", d.energy_error, ValueRange{});
  visit("carried_max_speed", carried.max_speed, ValueRange{});
  visit("carried_max_wave_speed", carried.max_wave_speed, ValueRange{});
  visit("initial_energy", carried.initial_energy, ValueRange{});
  visit("initial_rigid_energy", carried.initial_rigid_energy, ValueRange{});
  visit("driven_rigid_work", carried.driven_rigid_work, ValueRange{});
}

std::vector<std::string> names_of(const std::vector<BodySettings>& bodies) {
  std::vector<std::string> names;
  for (const auto& b : bodies) names.push_back(b.name);
  return names;
}
std::vector<std::string> names_of(const std::vector<RigidBodySettings>& bodies) {
  std::vector<std::string> names;
  for (const auto& b : bodies) names.push_back(b.name);
  return names;
}

// The values a field's bound allows, for n particles, nb bodies and nr rigid bodies.
ValueRange allowed(FieldBound bound, size_t n, size_t nb, size_t nr) {
  switch (bound) {
    case FieldBound::any: return {};
    case FieldBound::non_negative: return non_negative;
    case FieldBound::body_index: return {0, double(nb) - 1};
    case FieldBound::particle_id: return {0, double(n) - 1};
    case FieldBound::byte: return {0, 255};
    case FieldBound::rigid_body_or_none: return {-1, double(nr) - 1};
  }
  return {};
}

// Ids are a permutation of 0..n-1 (each within range already): the solver orders particles by them.
void check_permutation(const std::string& file, const std::string& dataset, const std::vector<uint32_t>& ids) {
  std::vector<char> seen(ids.size(), 0);
  for (uint32_t id : ids) {
    if (seen[id]) throw InputError(file, dataset, "id " + std::to_string(id) + " appears twice");
    seen[id] = 1;
  }
}

// [begin, end) ranges in column `begin_column` of a table: begin <= end, each continuing the
// previous one, from 0 to `limit`. An empty table passes: a run stopped before its first step
// has not sorted its particles into buckets yet.
void check_ranges(const std::string& file, const std::string& dataset, const std::vector<int64_t>& table,
                  size_t columns, size_t begin_column, int64_t limit, const std::string& what) {
  int64_t expected = 0;
  for (size_t row = 0; row < table.size() / columns; ++row) {
    const int64_t begin = table[row * columns + begin_column], end = table[row * columns + begin_column + 1];
    if (begin != expected || end < begin || end > limit)
      throw InputError(file, dataset, "row " + std::to_string(row) + ": " + what + " range [" + std::to_string(begin) +
                                          ", " + std::to_string(end) + ") does not continue the previous one within [0, " +
                                          std::to_string(limit) + ")");
    expected = end;
  }
  if (!table.empty() && expected != limit)
    throw InputError(file, dataset, "the " + what + " ranges end at " + std::to_string(expected) + ", not at " +
                                        std::to_string(limit));
}

// The buckets (rows of 7: coord x y z, begin, end, run_begin, run_end; ranges checked
// already) as a sort leaves them: in bucket order, each coordinate once, each bucket's runs
// covering exactly its particles. Several processes cut this table by bucket and keep their
// buckets' particles by these ranges (bucket_layout.hpp), so a table that merely tiles
// [0, n) twice over could hand a particle to two processes or to none.
void check_bucket_table(const std::string& file, const std::string& dataset, const std::vector<int64_t>& b,
                        const std::vector<int64_t>& r) {
  const std::vector<uint64_t> keys = bucket_order_keys(buckets_from_rows(b));
  for (size_t row = 0; row < keys.size(); ++row) {
    const int64_t* x = &b[7 * row];
    if (row > 0 && keys[row] <= keys[row - 1])
      throw InputError(file, dataset, "row " + std::to_string(row) + ": bucket (" + std::to_string(x[0]) + ", " +
                                          std::to_string(x[1]) + ", " + std::to_string(x[2]) +
                                          ") is not after the previous one in bucket order (a bucket twice?)");
    const bool covered = x[5] == x[6] ? x[3] == x[4] : r[3 * size_t(x[5]) + 1] == x[3] && r[3 * size_t(x[6] - 1) + 2] == x[4];
    if (!covered)
      throw InputError(file, dataset, "row " + std::to_string(row) + ": runs [" + std::to_string(x[5]) + ", " +
                                          std::to_string(x[6]) + ") do not cover exactly its particles [" +
                                          std::to_string(x[3]) + ", " + std::to_string(x[4]) + ")");
  }
}
}  // namespace

void Simulation::save_state(Hdf5File& f, const std::string& g) const { save_state(&f, g); }

void Simulation::save_state(Hdf5File* f, const std::string& g) const {
  // Several processes: the particle datasets and the bucket tables are laid out here at their
  // one-process size, and every process writes its rows of them once the file is closed
  // (save_state_rows): the file is the one a single process writes at this step.
  const Domain& domain = context_->domain;
  const bool needs_sort = domain.reduce_max(state_.needs_sort ? 1 : 0) > 0;
  const bool several = domain.process_count() > 1;
  const BucketPlacement placement = domain.bucket_placement(state_.buckets, state_.particles.size());
  const std::vector<uint8_t> present = domain.fields_present(state_.particles);
  if (!f) return;
  CheckpointWriter out(*f, g);
  out.strings("bodies", names_of(bodies_));
  if (!rigid_bodies_.empty()) out.strings("rigid_bodies", names_of(rigid_bodies_));

  CheckpointWriter particles = out.sub("particles");
  size_t field = 0;
  for_each_particle_field(state_.particles, [&](const ParticleField& info, const auto& values, const auto&) {
    if (!present[field++]) return;
    if (several)
      particles.reserve_rows<typename std::decay_t<decltype(values)>::value_type>(info.name, placement.particles);
    else
      particles.rows(info.name, values);
  });

  CheckpointWriter sorting = out.sub("buckets");
  if (several) {
    sorting.reserve_integers("buckets", placement.buckets, bucket_row_width);
    sorting.reserve_integers("runs", placement.runs, run_row_width);
  } else {
    sorting.integers("buckets", bucket_rows(state_.buckets.buckets()), bucket_row_width);
    sorting.integers("runs", run_rows(state_.buckets.runs()), run_row_width);
  }
  sorting.integer("needs_sort", needs_sort);

  CheckpointWriter solver = out.sub("solver");
  const StepDiagnostics& d = state_.diagnostics;
  solver.integer("step", d.step);
  for_each_solver_scalar(d, state_.carried, [&](const char* name, Real value, ValueRange) { solver.scalar(name, value); });
  solver.rows("body_displacement", d.body_displacement);
  solver.rows("reaction", d.reaction);
  solver.rows("initial_centre", state_.carried.initial_centre);

  CheckpointWriter boundaries = out.sub("boundaries");
  for (const auto& b : state_.boundaries) {
    CheckpointWriter own = boundaries.sub(checkpoint_name(b));
    std::visit([&](const auto& boundary) { boundary.save(own); }, b);
  }
}

void Simulation::save_state_rows(const std::string& path, const std::string& g) const {
  const Domain& domain = context_->domain;
  if (domain.process_count() == 1) return;  // save_state wrote them
  const size_t n = state_.particles.size();
  const OneProcessRows rows =
      one_process_rows({state_.buckets.buckets(), state_.buckets.runs()}, domain.bucket_placement(state_.buckets, n), n);
  const std::vector<uint8_t> present = domain.fields_present(state_.particles);
  domain.write_shared_rows(path, [&](Hdf5File& file) {
    CheckpointWriter particles = CheckpointWriter::existing(file, g + "/particles");
    const bool writes = !rows.particle_blocks.empty();  // every process its rows, in one collective write each
    size_t field = 0;
    for_each_particle_field(state_.particles, [&](const ParticleField& f, const auto& values, const auto&) {
      if (!present[field++]) return;
      if (writes)
        particles.write_rows(f.name, values, rows.particle_blocks);
      else
        particles.write_rows(f.name, std::decay_t<decltype(values)>{}, {});
    });
    CheckpointWriter sorting = CheckpointWriter::existing(file, g + "/buckets");
    sorting.write_rows("buckets", rows.buckets, rows.bucket_blocks);
    sorting.write_rows("runs", rows.runs, rows.run_blocks);
  });
}

void Simulation::load_state(const Hdf5File& f, const std::string& g) {
  const CheckpointReader in(f, g);
  const size_t n = state_.particles.size();
  if (in.strings("bodies") != names_of(bodies_))
    throw InputError(f.path(), g + "/bodies", "the checkpoint's bodies differ from the scene's (another scene?)");
  const auto rigid_names = names_of(rigid_bodies_);
  if (!rigid_names.empty() && (!in.has("rigid_bodies") || in.strings("rigid_bodies") != rigid_names))
    throw InputError(f.path(), g + "/rigid_bodies", "the checkpoint's rigid bodies differ from the scene's");

  // Everything is read and checked as it is read, before anything is changed: a refused
  // checkpoint leaves the simulation as it was. Indices stay within the tables they point
  // into (bodies, particles, buckets, runs), so a corrupted file cannot crash the run.
  const CheckpointReader particles_in = in.sub("particles");
  const size_t nb = bodies_.size(), nr = rigid_bodies_.size();
  Particles p = state_.particles;
  std::vector<std::string> derived;  // history columns the checkpoint lacks, derived below
  for_each_particle_field(p, [&](const ParticleField& field, auto& values, const auto&) {
    if (field.optional && values.empty()) return;  // the scene's run does not use it
    if (field.derived_when_missing && !particles_in.has(field.name)) {
      derived.push_back(field.name);
      return;
    }
    if (field.optional && !particles_in.has(field.name))
      throw InputError(f.path(), g + "/particles/" + field.name, std::string("missing: ") + field.when_missing);
    values = particles_in.rows<typename std::decay_t<decltype(values)>::value_type>(field.name, n,
                                                                                   allowed(field.bound, n, nb, nr));
    if constexpr (std::is_same_v<std::decay_t<decltype(values)>, std::vector<uint32_t>>)
      if (field.bound == FieldBound::particle_id) check_permutation(f.path(), g + "/particles/" + field.name, values);
  });

  // Buckets and runs: contiguous particle ranges; each bucket's runs a contiguous range of runs.
  const CheckpointReader sorting = in.sub("buckets");
  const auto r = sorting.integers("runs", 3, 0, int64_t(n));
  for (size_t i = 0; i < r.size() / 3; ++i)
    if (r[3 * i] >= int64_t(nb))
      throw InputError(f.path(), g + "/buckets/runs",
                       "row " + std::to_string(i) + ": body " + std::to_string(r[3 * i]) + " of " + std::to_string(nb));
  check_ranges(f.path(), g + "/buckets/runs", r, 3, 1, int64_t(n), "particle");
  const auto b = sorting.integers("buckets", 7, std::numeric_limits<int32_t>::min() / 8,
                                  std::numeric_limits<int32_t>::max() / 8);
  check_ranges(f.path(), g + "/buckets/buckets", b, 7, 3, int64_t(n), "particle");
  check_ranges(f.path(), g + "/buckets/buckets", b, 7, 5, int64_t(r.size() / 3), "run");
  check_bucket_table(f.path(), g + "/buckets/buckets", b, r);
  BucketTables tables{buckets_from_rows(b), runs_from_rows(r)};
  const bool needs_sort = sorting.integer("needs_sort", 0, 1) != 0;
  if (b.empty() && n > 0 && !needs_sort)
    throw InputError(f.path(), g + "/buckets/needs_sort",
                     "0 with no buckets: the particles would be in no bucket (1 sorts them first)");

  const CheckpointReader solver = in.sub("solver");
  StepDiagnostics d = state_.diagnostics;
  d.step = solver.integer("step", 0);
  CarriedState carried;
  for_each_solver_scalar(d, carried, [&](const char* name, Real& value, ValueRange range) {
    value = solver.scalar(name, range);
  });
  d.body_displacement = solver.rows<Vec3>("body_displacement", nb);
  d.reaction = solver.rows<Vec3>("reaction", nb);
  carried.initial_centre = solver.rows<Vec3>("initial_centre", nb);

  const CheckpointReader boundaries_in = in.sub("boundaries");
  std::vector<Boundary> boundaries = state_.boundaries;
  for (auto& boundary_slot : boundaries) {
    const CheckpointReader own = boundaries_in.sub(checkpoint_name(boundary_slot));
    std::visit([&](auto& boundary) { boundary.load(own); }, boundary_slot);
  }

  // Several processes: each keeps its share of the buckets, as they are (no re-sort).
  context_->domain.distribute_buckets(p, tables);
  state_.particles = std::move(p);
  if (!derived.empty()) derive_history_from_state(state_, *context_, derived);
  context_->fixed_body_nodes.ready = false;  // from the restored positions
  state_.buckets.restore(std::move(tables.buckets), std::move(tables.runs));
  state_.needs_sort = needs_sort;
  if (!state_.needs_sort) compute_boxes_from_positions(state_, *context_);
  state_.carried = std::move(carried);
  context_->refresh_needed = false;
  state_.boundaries = std::move(boundaries);
  state_.diagnostics = std::move(d);
  refresh_rigid_states();
}

}  // namespace latmpm::mpm
