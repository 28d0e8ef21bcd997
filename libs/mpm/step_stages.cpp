// The stages of a step that do not depend on the shape function (step_stages.hpp): bucket
// boxes, the passes' sums and their checks, the node update with the boundaries, penalty
// contact, and the carried speeds and energies the stable time step uses.
#include "mpm/step_stages.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/errors.hpp"
#include "mpm/body.hpp"
#include "mpm/bucket_partition.hpp"

namespace latmpm::mpm {

void compute_boxes_from_positions(SolverState& s, StepContext& c) {
  const Real inv_h = 1 / c.settings.cell_size;
  auto& list = s.buckets.buckets();
  const Particles& ps = s.particles;
  c.columns.assign(list.size(), BucketColumns{});
  std::atomic<bool> outside_drift{false};
  tbb::parallel_for(size_t(0), list.size(), [&](size_t bi) {
    Bucket& b = list[bi];
    std::array<int, 3> lo{max_cell_coord, max_cell_coord, max_cell_coord}, hi{-max_cell_coord, -max_cell_coord, -max_cell_coord};
    for (uint32_t r = b.run_begin; r < b.run_end; ++r) {
      const BodyRun& run = s.buckets.runs()[r];
      if (c.body_info[size_t(run.body)].marked_once) continue;  // the step leaves them out
      for (uint32_t p = run.begin; p < run.end; ++p) {
        const auto cell = cell_of(ps.position[p], inv_h);
        for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], cell[a]), hi[a] = std::max(hi[a], cell[a]);
        if (ParticleBuckets::within_drift(b, cell))
          c.columns[bi].add_cell(b, cell);
        else
          outside_drift = true;
      }
    }
    b.box_lo = lo;
    b.box_hi = hi;
  });
  // A point its bucket's columns cannot hold (a loaded state whose buckets no longer fit)
  // would scatter into nodes nobody clears or adds: sort before the next scatter.
  if (outside_drift) s.needs_sort = true;
}

void take_cell_ranges(SolverState& s, StepContext& c) {
  auto& list = s.buckets.buckets();
  c.columns.resize(list.size());
  for (size_t bi = 0; bi < list.size(); ++bi) {
    list[bi].box_lo = c.tallies[bi].cell_min;
    list[bi].box_hi = c.tallies[bi].cell_max;
    c.columns[bi] = c.tallies[bi].cells;
    if (c.tallies[bi].drifted) s.needs_sort = true;
  }
  if (s.needs_sort) return;
  // A bucket whose gather tracked no cell and that holds points the step moves: sort.
  // (Buckets of a fixed body's points marked once have no cells and need none.)
  for (size_t bi = 0; bi < list.size(); ++bi) {
    const Bucket& b = list[bi];
    if (b.box_lo[0] <= b.box_hi[0]) continue;
    for (uint32_t r = b.run_begin; r < b.run_end; ++r)
      if (!c.body_info[size_t(s.buckets.runs()[r].body)].marked_once) s.needs_sort = true;
  }
}

namespace {
[[noreturn]] void throw_fault(const SolverState& s, const StepContext& c, ParticleFault fault, uint32_t p) {
  const Particles& ps = s.particles;
  std::ostringstream msg;
  msg.precision(6);
  msg << "step " << s.diagnostics.step + 1 << " (t = " << s.diagnostics.time << " s): particle " << ps.id[p]
      << " of body '" << c.bodies[size_t(ps.body[p])].name << "' at (" << ps.position[p][0] << ", "
      << ps.position[p][1] << ", " << ps.position[p][2] << ") m ";
  switch (fault) {
    case ParticleFault::not_finite: msg << "has a NaN or infinite velocity, position or stress"; break;
    case ParticleFault::inverted:
      msg << "is inverted or crushed (J = " << ps.deformation[p].determinant() << " <= " << c.settings.min_jacobian
          << ")";
      break;
    case ParticleFault::left_grid: msg << "left the grid (more than " << max_cell_coord << " cells from the origin)"; break;
    case ParticleFault::none: break;
  }
  msg << "; try a smaller cfl or time step";
  throw NumericalError(msg.str());
}
}  // namespace

void absorb_tallies(SolverState& s, StepContext& c, bool velocity, bool position, bool gradient) {
  PassSums local;
  // per bucket: kinetic, strain, dissipation, gravity power, blend dissipation, increment energy
  std::vector<Real> rows;
  for (size_t bi = 0; bi < c.tallies.size(); ++bi) {
    const BucketTally& t = c.tallies[bi];
    if (t.fault != ParticleFault::none) throw_fault(s, c, t.fault, t.fault_particle);
    rows.insert(rows.end(),
                {t.kinetic, t.strain, t.dissipation, t.gravity_power, t.blend_dissipation, t.increment_energy});
    local.max_speed_sq = std::max(local.max_speed_sq, t.max_speed_sq);
    local.max_wave_speed_sq = std::max(local.max_wave_speed_sq, t.max_wave_speed_sq);
  }
  const std::vector<Real> sum = c.domain.sum_in_order(bucket_order_keys(s.buckets.buckets()), rows, 6);
  PassSums& sums = c.sums;
  if (velocity) {
    sums.kinetic = sum[0];
    sums.blend_dissipation = sum[4];
    // The FLIP update raises the points' kinetic energy by Σ_I p_I·Δv_I + Σ_p ½ m_p |Δv_p|²
    // (p_I = Σ_p S_Ip m_p v_p); the step's work, taken at the new nodal velocities (the
    // strain rate, the points' moves), is dt Σ_I f_I·v_I^{n+1} = Σ_I p_I·Δv_I + Σ_I m_I |Δv_I|².
    // So the balance changes by −Σ_p ½ m_p |Δv_p|² − (Σ_I m_I |Δv_I|² − Σ_p m_p |Δv_p|²): the
    // first term is the explicit step's kick at the points, which the strain energy's
    // second-order gain ½ dt² V L:C:L returns on average (a bounded oscillation); the second
    // is the projection's definite loss (Jensen: ≥ 0 for weights ≥ 0 that sum to one),
    // booked like the blend's (docs/solver.md, "Energy"). Only where the strain rate is taken
    // at the new nodal velocities (USL, `gradient` in this pass): MUSL's work is at the
    // remapped velocity, Σ_p m_p v_p^{n+1}·Δv_p, and USF's at v^n, Σ_I p_I·Δv_I, so their
    // balances change by ∓Σ_p ½ m_p |Δv_p|² alone, with no projection term.
    sums.transfer_dissipation = gradient ? 2 * (sums.node_increment_energy - sum[5]) : 0;
    sums.max_speed_sq = c.domain.reduce_max(local.max_speed_sq);
  }
  if (position) {
    sums.gravity_power = sum[3];
    take_cell_ranges(s, c);
  }
  if (gradient) {
    sums.strain = sum[1];
    sums.dissipation = sum[2];
    sums.max_wave_speed_sq = c.domain.reduce_max(local.max_wave_speed_sq);
  }
}

BoundaryPass boundary_pass(SolverState& s, StepContext& c, Real dt) {
  return {s.grid, c.settings.cell_size, dt, c.settings.gravity, &c.reactions,
          c.penalty_contact ? &c.contact : nullptr, &c.domain};
}

namespace {
// The grid's block keys, for per-block sums in block order (a block several processes hold
// counts once: Domain::sum_in_order).
std::vector<uint64_t> block_keys(const SparseGrid& grid) {
  std::vector<uint64_t> keys(grid.block_count());
  for (size_t b = 0; b < keys.size(); ++b) keys[b] = grid.key(b);
  return keys;
}
}  // namespace

void update_nodes(SolverState& s, StepContext& c, Real dt) {
  std::vector<Real> rows = update_grid_velocities(s.grid, dt, c.settings.gravity, c.body_info);
  c.reactions = reactions_from_sums(c.domain.sum_in_order(block_keys(s.grid), rows, 4 * c.body_info.size()));
  constrain_boundaries(s, c, dt);
}

Real node_increment_energy(SolverState& s, StepContext& c) {
  return c.domain.sum_in_order(block_keys(s.grid), node_increment_energy_rows(s.grid), 1)[0];
}

void constrain_boundaries(SolverState& s, StepContext& c, Real dt) {
  BoundaryPass pass = boundary_pass(s, c, dt);
  for (auto& b : s.boundaries) std::visit([&](auto& boundary) { boundary.constrain(pass); }, b);
}

void impose_boundaries(SolverState& s, StepContext& c, int lane) {
  BoundaryPass pass = boundary_pass(s, c, 0);
  for (auto& b : s.boundaries) std::visit([&](auto& boundary) { boundary.impose(pass, lane); }, b);
}

void enable_penalty_contact(SolverState& s, StepContext& c) {
  c.penalty_contact = true;
  Particles& ps = s.particles;
  if (ps.contact_body.empty()) ps.contact_body.assign(ps.size(), -1), ps.contact_anchor.assign(ps.size(), Vec3::Zero());
  c.contact_materials.assign(c.body_info.size(), ContactMaterial{});
  for (size_t b = 0; b < c.body_info.size(); ++b) {
    if (c.body_info[b].role != BodyRole::deformable) continue;
    const Real c2 = std::visit([](const auto& m) { return m.wave_speed_squared(1); }, c.body_info[b].model);
    c.contact_materials[b] = {true, default_contact_stiffness_per_mass(c2, c.settings.cell_size)};
  }
  c.contact_rate_sq = c.domain.reduce_max(stable_contact_rate_squared(ps, c.contact_materials, c.rigid_bodies));
}

void update_contact_forces(SolverState& s, StepContext& c) {
  // This process's points; on several processes add_contact_forces forms the sums.
  update_penalty_contacts(s.particles, c.contact_materials, c.rigid_bodies, s.diagnostics.rigid, c.contact);
}

Real ddmp_small_mass(const SolverState& s, StepContext& c) {
  if (c.ddmp_small_mass < 0) {
    const Particles& ps = s.particles;
    Real density = std::numeric_limits<Real>::infinity();
    for (size_t p = 0; p < ps.size(); ++p)
      if (c.body_info[size_t(ps.body[p])].role == BodyRole::deformable && ps.volume0[p] > 0)
        density = std::min<Real>(density, ps.mass[p] / ps.volume0[p]);
    density = c.domain.reduce_min(density);
    const Real h = c.settings.cell_size;
    c.ddmp_small_mass = std::isfinite(density) ? c.settings.ddmp_small_mass_fraction * density * h * h * h : 0;
  }
  return c.ddmp_small_mass;
}

Vec3 centre_of_mass(const SolverState& s, const StepContext& c, size_t body) {
  // The body's run in each bucket (one at most), in bucket order.
  std::vector<uint64_t> keys;
  std::vector<Real> rows;
  const auto& runs = s.buckets.runs();
  for (const Bucket& b : s.buckets.buckets())
    for (uint32_t r = b.run_begin; r < b.run_end; ++r)
      if (size_t(runs[r].body) == body) {
        keys.push_back(bucket_order_key(b));
        const Vec3& mx = c.run_tallies[r].mass_position;
        rows.insert(rows.end(), {mx[0], mx[1], mx[2], c.run_tallies[r].mass});
      }
  const std::vector<Real> sum = c.domain.sum_in_order(keys, rows, 4);
  const Real m = sum[3];
  return m > 0 ? Vec3(Vec3(sum[0], sum[1], sum[2]) / m) : Vec3::Zero();
}

std::string fastest_particle(const SolverState& s, const StepContext& c) {
  const Particles& ps = s.particles;
  size_t fastest = ps.size();
  for (size_t p = 0; p < ps.size(); ++p)
    if (c.body_info[size_t(ps.body[p])].role == BodyRole::deformable &&
        (fastest == ps.size() || ps.velocity[p].squaredNorm() > ps.velocity[fastest].squaredNorm()))
      fastest = p;
  std::string mine = "no deformable particle";
  double speed_sq = -1;  // below any particle's, so a process without one never names itself
  if (fastest < ps.size()) {
    std::ostringstream msg;
    msg.precision(6);
    const auto& x = ps.position[fastest];
    speed_sq = double(ps.velocity[fastest].squaredNorm());
    if (!std::isfinite(speed_sq)) speed_sq = std::numeric_limits<double>::infinity();  // the one to name
    msg << "the fastest particle: " << ps.id[fastest] << " of body '" << c.bodies[size_t(ps.body[fastest])].name
        << "' at (" << x[0] << ", " << x[1] << ", " << x[2] << ") m, " << ps.velocity[fastest].norm() << " m/s";
    mine = msg.str();
  }
  // With several processes each holds its own particles: the one of the whole domain.
  return c.domain.text_of_largest(speed_sq, mine);
}

Real energy_density(const SolverState& s, const StepContext& c, size_t p) {
  const Particles& ps = s.particles;
  const BodyInfo& body = c.body_info[size_t(ps.body[p])];
  return std::visit([&](const auto& m) {
    constexpr size_t count = history_size<std::decay_t<decltype(m)>>;
    Real history[count > 0 ? count : 1] = {};
    for (size_t k = 0; k < count; ++k) history[k] = ps.history[body.history_columns[k]].values[p];
    return strain_energy_density(m, ps.deformation[p].cast<Real>(), ps.stress[p].cast<Real>(), history);
  }, body.model);
}

CarriedState carried_from_particles(const SolverState& s, const StepContext& c) {
  const Particles& ps = s.particles;
  CarriedState carried = s.carried;
  Real max_speed = 0, max_wave_speed = 0, initial_energy = 0;
  const size_t nb = c.body_info.size();
  for (size_t b = 0; b < nb; ++b) {
    if (c.body_info[b].role == BodyRole::deformable)
      max_wave_speed = std::max(max_wave_speed,
          std::sqrt(std::visit([](const auto& m) { return m.wave_speed_squared(1); }, c.body_info[b].model)));
    else
      max_speed = std::max(max_speed, c.body_info[b].velocity.norm());
  }
  for (const auto& r : s.diagnostics.rigid) max_speed = std::max(max_speed, r.velocity.norm());
  std::vector<Vec3> mx(nb, Vec3::Zero());
  std::vector<Real> mass(nb, 0);
  for (size_t p = 0; p < ps.size(); ++p) {
    const size_t b = size_t(ps.body[p]);
    mx[b] += Real(ps.mass[p]) * ps.position[p];
    mass[b] += ps.mass[p];
    if (c.body_info[b].role != BodyRole::deformable) continue;
    max_speed = std::max(max_speed, ps.velocity[p].cast<Real>().norm());
    initial_energy += Real(0.5) * ps.mass[p] * ps.velocity[p].cast<Real>().squaredNorm() + ps.volume0[p] * energy_density(s, c, p);
  }
  carried.max_speed = c.domain.reduce_max(max_speed);
  carried.max_wave_speed = c.domain.reduce_max(max_wave_speed);
  carried.initial_energy = c.domain.reduce_sum(initial_energy);
  carried.initial_centre.assign(nb, Vec3::Zero());
  for (size_t b = 0; b < nb; ++b) {
    mx[b] = c.domain.reduce_sum(mx[b]);
    mass[b] = c.domain.reduce_sum(mass[b]);
    if (mass[b] > 0) carried.initial_centre[b] = mx[b] / mass[b];
  }
  return carried;
}

void derive_history_from_state(SolverState& s, const StepContext& c, const std::vector<std::string>& names) {
  Particles& ps = s.particles;
  // The columns to set, decided once: derived, and named (or no names given).
  std::vector<bool> wanted(ps.history.size());
  for (size_t k = 0; k < ps.history.size(); ++k)
    wanted[k] = ps.history[k].derived &&
                (names.empty() || std::find(names.begin(), names.end(), ps.history[k].name) != names.end());
  if (std::find(wanted.begin(), wanted.end(), true) == wanted.end()) return;
  for (size_t p = 0; p < ps.size(); ++p) {
    const BodyInfo& body = c.body_info[size_t(ps.body[p])];
    if (body.role != BodyRole::deformable) continue;
    std::visit([&](const auto& m) {
      using Model = std::decay_t<decltype(m)>;
      if constexpr (derives_history<Model>::value) {
        constexpr auto& variables = material_history<Model>::variables;
        Real history[variables.size()];
        for (size_t k = 0; k < variables.size(); ++k) history[k] = ps.history[body.history_columns[k]].values[p];
        Real stress[6];
        for (int k = 0; k < 6; ++k) stress[k] = ps.stress[p][k];
        m.history_from_state(make_deformation(Mat3::Zero(), ps.deformation[p].cast<Real>(), 0), stress, history);
        for (size_t k = 0; k < variables.size(); ++k)
          if (wanted[body.history_columns[k]]) ps.history[body.history_columns[k]].values[p] = history[k];
      }
    }, body.model);
  }
}

void refresh_carried(SolverState& s, StepContext& c) {
  // Points set up with a stress before the first step (Simulation::mutable_particles) hold
  // its energy from the start.
  if (s.diagnostics.step == 0) derive_history_from_state(s, c, {});
  s.carried = carried_from_particles(s, c);
  c.refresh_needed = false;
}

// cfl · h/(c + |v|); with penalty contact cfl · 2/√(ω² + κ/m), ω = 2(c + |v|)/h the
// grid's highest frequency and κ/m the largest of a contact spring (rigid_contact.hpp).
Real stable_time_step(const SolverState& s, const StepContext& c) {
  const CarriedState carried = c.refresh_needed ? carried_from_particles(s, c) : s.carried;
  const Real speed = carried.max_wave_speed + carried.max_speed;
  const Settings& st = c.settings;
  if (c.contact_rate_sq > 0) {
    const Real rate = speed / st.cell_size;
    return st.cfl / std::sqrt(rate * rate + c.contact_rate_sq / 4);
  }
  return speed > 0 ? st.cfl * st.cell_size / speed : std::numeric_limits<Real>::infinity();
}

}  // namespace latmpm::mpm
