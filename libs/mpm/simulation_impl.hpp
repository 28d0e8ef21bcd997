// The solver's private state and the passes of a step, shared by simulation.cpp (the step
// and its diagnostics) and simulation_stages.cpp (single stages, for tests). Not installed
// for users: simulation.hpp is the interface.
#pragma once
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/errors.hpp"
#include "mpm/ddmp_grid.hpp"
#include "mpm/domain.hpp"
#include "mpm/grid_update.hpp"
#include "mpm/particle_buckets.hpp"
#include "mpm/rigid_contact.hpp"
#include "mpm/shape_functions.hpp"
#include "mpm/simulation.hpp"
#include "mpm/sparse_grid.hpp"
#include "mpm/transfer.hpp"

namespace latmpm::mpm {

// The scatter and gather modes the three schemes combine.
using ScatterAll = ScatterMode<true, lane::momentum, true, true>;         // m, p, f, constraints
using ScatterMomentum = ScatterMode<true, lane::momentum, false, true>;    // m, p, constraints
using ScatterRemap = ScatterMode<false, lane::force, false, false>;       // p into lanes 4–6
using ScatterForce = ScatterMode<false, -1, true, false>;                 // f only
using GatherAll = GatherMode<true, true, lane::momentum>;
using GatherVelocity = GatherMode<true, false, -1>;
using GatherMotion = GatherMode<true, true, -1>;
using GatherStrain = GatherMode<false, false, lane::force>;
using GatherStrainAndPosition = GatherMode<false, true, lane::force>;

struct Simulation::Impl {
  Simulation& sim;
  std::vector<BodyInfo> body_info;
  ParticleBuckets buckets;
  std::vector<BlockTable> tables;
  SparseGrid grid;
  Domain domain;  // other processes' parts (domain.hpp): nothing to do for one
  tbb::task_arena arena;
  tbb::enumerable_thread_specific<BucketBuffer> buffers;
  std::vector<BucketTally> tallies;
  std::vector<RunTally> run_tallies;
  bool needs_sort = true;
  bool grid_holds_velocity = false;  // lanes 1–3: momentum (false) or velocity (true)

  // State carried between steps.
  Real max_speed = 0;            // m/s, deformable and driven points
  Real max_wave_speed = 0;       // m/s
  Real initial_energy = 0;       // J
  std::vector<Vec3> initial_centre;  // per body, m
  Reactions reactions;
  DdmpNodalValues ddmp_nodal;   // DDMP: σ^d, L and small-mass shares per node (ddmp_grid.hpp)
  Real ddmp_small_mass = -1;    // DDMP: below this a node's lanes go to its neighbours, kg (set on first use)
  // Penalty contact with rigid bodies (rigid_contact.hpp): off until a penalty body is added.
  bool penalty_contact = false;
  std::vector<ContactMaterial> contact_materials;  // per point body
  ContactForces contact;                           // of the current step, in particle order
  Real contact_rate_sq = 0;                        // largest κ_p/m_p, 1/s²

  explicit Impl(Simulation& s, int threads)
      : sim(s), arena(threads > 0 ? threads : tbb::task_arena::automatic) {}

  const Settings& settings() const { return sim.settings_; }
  DdmpPartition ddmp_partition() const { return {settings().ddmp_alpha_peak, settings().ddmp_alpha_exponent}; }
  Particles& particles() { return sim.particles_; }

  // Calls f(Shape{}) with the policy the run uses: the settings' shape function, DDMP with
  // its smoothed part on the grid (DdmpGridShape) unless Settings::ddmp_on_grid is off.
  template <class F>
  void with_solver_shape(F&& f) {
    with_shape_function(settings().shape_function, [&](auto shape) {
      if constexpr (std::is_same_v<decltype(shape), DdmpShape>)
        if (settings().ddmp_on_grid) return f(DdmpGridShape{});
      return f(shape);
    });
  }
  // DDMP on the grid: its smoothed force reaches one node beyond the particles' cells.
  template <class Shape>
  static constexpr int grid_halo = has_grid_smoothed_gradient<Shape>::value ? 1 : 0;

  // --- Buckets and the active grid -------------------------------------------------------

  // Node boxes from the particles' cells (after a sort or when positions were set).
  void compute_boxes_from_positions() {
    const Real inv_h = 1 / settings().cell_size;
    auto& list = buckets.buckets();
    tbb::parallel_for(size_t(0), list.size(), [&](size_t bi) {
      Bucket& b = list[bi];
      std::array<int, 3> lo{max_cell_coord, max_cell_coord, max_cell_coord}, hi{-max_cell_coord, -max_cell_coord, -max_cell_coord};
      for (uint32_t p = b.begin; p < b.end; ++p) {
        const auto c = cell_of(particles().position[p], inv_h);
        for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], c[a]), hi[a] = std::max(hi[a], c[a]);
      }
      b.box_lo = lo;
      b.box_hi = hi;
    });
  }

  template <class Shape>
  void prepare_grid() {
    if (needs_sort) {
      domain.migrate_particles(particles());
      buckets.sort(particles(), settings().cell_size);
      compute_boxes_from_positions();
      needs_sort = false;
    }
    // Bucket boxes hold cell ranges until here; widen them by the stencil's reach.
    std::vector<uint64_t> keys;
    auto& list = buckets.buckets();
    constexpr int bw = SparseGrid::block_width;
    for (Bucket& b : list) {
      for (int a = 0; a < 3; ++a) {
        b.box_lo[a] += Shape::reach_below;
        b.box_hi[a] += Shape::reach_above;
      }
      constexpr int e = grid_halo<Shape>;
      for (int i = floor_div(b.box_lo[0] - e, bw); i <= floor_div(b.box_hi[0] + e, bw); ++i)
        for (int j = floor_div(b.box_lo[1] - e, bw); j <= floor_div(b.box_hi[1] + e, bw); ++j)
          for (int k = floor_div(b.box_lo[2] - e, bw); k <= floor_div(b.box_hi[2] + e, bw); ++k)
            keys.push_back(SparseGrid::block_key(i, j, k));
    }
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    grid.set_active_blocks(keys);
    tables.resize(list.size());
    for (size_t bi = 0; bi < list.size(); ++bi) {
      const Bucket& b = list[bi];
      int first[3];
      for (int a = 0; a < 3; ++a) first[a] = first_table_block(b.coord[a]);
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
          for (int k = 0; k < 4; ++k)
            tables[bi][(i * 4 + j) * 4 + k] = grid.find(first[0] + i, first[1] + j, first[2] + k);
    }
    if constexpr (has_smoothed_gradient<Shape>::value) prepare_ddmp_nodal_values(grid, ddmp_nodal);
    clear_grid(grid);
    grid_holds_velocity = false;
    tallies.assign(list.size(), BucketTally{});
    run_tallies.assign(buckets.runs().size(), RunTally{});
  }

  // After a pass that moved the particles: the buckets' cell ranges for the next step.
  void take_cell_ranges() {
    auto& list = buckets.buckets();
    for (size_t bi = 0; bi < list.size(); ++bi) {
      list[bi].box_lo = tallies[bi].cell_min;
      list[bi].box_hi = tallies[bi].cell_max;
      if (tallies[bi].drifted) needs_sort = true;
    }
    if (needs_sort) return;
    // Buckets holding only rigid points of a fixed body have no tally cells; keep them valid.
    for (size_t bi = 0; bi < list.size(); ++bi)
      if (list[bi].box_lo[0] > list[bi].box_hi[0]) needs_sort = true;
  }

  // --- Transfers -----------------------------------------------------------------------

  template <class Shape, class Mode>
  void scatter() {
    const auto& list = buckets.buckets();
    constexpr bool nodal_stress = Mode::force && has_grid_smoothed_gradient<Shape>::value;
    if constexpr (nodal_stress) clear_ddmp_nodal_values(ddmp_nodal);
    for (const auto& colour : buckets.colours()) {
      // Buckets of one colour are two buckets apart: their boxes never overlap.
      tbb::parallel_for(tbb::blocked_range<size_t>(0, colour.size(), 1), [&](const tbb::blocked_range<size_t>& r) {
        BucketBuffer& buffer = buffers.local();
        for (size_t c = r.begin(); c < r.end(); ++c) {
          const Bucket& b = list[colour[c]];
          buffer.attach(b);
          buffer.ddmp_alpha = ddmp_partition();
          clear_box(b, buffer);
          if constexpr (nodal_stress) clear_ddmp_box(b, tables[colour[c]], buffer);
          scatter_bucket<Shape, Mode>(b, &buckets.runs()[b.run_begin], particles(), body_info.data(),
                                      settings().cell_size, buffer);
          add_box_to_grid(b, tables[colour[c]], grid, buffer);
          if constexpr (nodal_stress) add_ddmp_box_to_grid(b, tables[colour[c]], buffer, ddmp_nodal);
        }
      });
    }
    domain.exchange_halo(grid);
    if constexpr (nodal_stress) {  // Paper A Eq. 4: the smoothed part of the force on the grid
      add_ddmp_smoothed_force(grid, ddmp_nodal, settings().cell_size);
    }
  }

  template <class Shape, class Mode>
  void gather(Real dt) {
    const auto& list = buckets.buckets();
    const GatherParameters parameters{settings().cell_size, dt, settings().flip_blend, settings().gravity,
                                      settings().min_jacobian};
    constexpr bool nodal_gradient = Mode::gradient_lane >= 0 && has_grid_smoothed_gradient<Shape>::value;
    if constexpr (nodal_gradient) ddmp_nodal_velocity_gradient(grid, Mode::gradient_lane, settings().cell_size, ddmp_nodal);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, list.size(), 1), [&](const tbb::blocked_range<size_t>& r) {
      BucketBuffer& buffer = buffers.local();
      for (size_t bi = r.begin(); bi < r.end(); ++bi) {
        const Bucket& b = list[bi];
        buffer.attach(b);
        buffer.ddmp_alpha = ddmp_partition();
        copy_box_from_grid(b, tables[bi], grid, buffer);
        if constexpr (nodal_gradient) copy_ddmp_box_from_grid(b, tables[bi], ddmp_nodal, buffer);
        gather_bucket<Shape, Mode>(b, &buckets.runs()[b.run_begin], particles(), body_info.data(), parameters,
                                   buffer, tallies[bi], &run_tallies[b.run_begin]);
      }
    });
    absorb_tallies(Mode::velocity, Mode::position, Mode::gradient_lane >= 0);
  }

  // --- DDMP's small-mass nodes (ddmp_grid.hpp) --------------------------------------------

  // ε ρ h³, ρ the smallest density of a deformable body's points (Settings::ddmp_small_mass_fraction).
  Real small_mass() {
    if (ddmp_small_mass < 0) {
      const Particles& ps = particles();
      Real density = std::numeric_limits<Real>::infinity();
      for (size_t p = 0; p < ps.size(); ++p)
        if (body_info[size_t(ps.body[p])].role == BodyRole::deformable && ps.volume0[p] > 0)
          density = std::min(density, ps.mass[p] / ps.volume0[p]);
      const Real h = settings().cell_size;
      ddmp_small_mass = std::isfinite(density) ? settings().ddmp_small_mass_fraction * density * h * h * h : 0;
    }
    return ddmp_small_mass;
  }
  // After a scatter: small-mass nodes hand lanes [first, first + count) on to their
  // neighbours (`find`: decide which nodes those are, from the mass just mapped).
  template <class Shape>
  void ddmp_hand_on(int first, int count, bool find) {
    if constexpr (has_smoothed_gradient<Shape>::value) {
      if (find) find_ddmp_small_mass_nodes(grid, small_mass(), ddmp_nodal);
      move_ddmp_small_mass_lanes(grid, small_mass(), first, count, ddmp_nodal);
    }
  }
  // After the nodal velocities: the small-mass nodes' lanes read back from their neighbours.
  template <class Shape>
  void ddmp_read_back(int first, int count) {
    if constexpr (has_smoothed_gradient<Shape>::value)
      spread_ddmp_small_mass_lanes(grid, small_mass(), first, count, ddmp_nodal);
  }

  // --- Schemes (Nairn 2003; Bardenhagen 2002) -------------------------------------------

  template <class Shape>
  void step_usl(Real dt) {
    prepare_grid<Shape>();
    scatter<Shape, ScatterAll>();
    add_contact_forces<Shape>();
    ddmp_hand_on<Shape>(lane::mass, 7, true);
    reactions = update_grid_velocities(grid, dt, settings().gravity, body_info);
    constrain_boundaries(dt);
    ddmp_read_back<Shape>(lane::momentum, 6);
    gather<Shape, GatherAll>(dt);
  }

  template <class Shape>
  void step_musl(Real dt) {
    prepare_grid<Shape>();
    scatter<Shape, ScatterAll>();
    add_contact_forces<Shape>();
    ddmp_hand_on<Shape>(lane::mass, 7, true);
    reactions = update_grid_velocities(grid, dt, settings().gravity, body_info);
    constrain_boundaries(dt);
    ddmp_read_back<Shape>(lane::momentum, 6);
    gather<Shape, GatherVelocity>(dt);
    // Map the updated particle momentum back (lanes 4–6) and take L from that velocity.
    clear_grid_lanes(grid, lane::force, 3);
    scatter<Shape, ScatterRemap>();
    ddmp_hand_on<Shape>(lane::force, 3, false);
    grid_velocity_from_momentum(grid, lane::force, lane::force, body_info);
    ddmp_read_back<Shape>(lane::force, 3);
    impose_boundaries(lane::force);
    gather<Shape, GatherStrainAndPosition>(dt);
  }

  template <class Shape>
  void step_usf(Real dt) {
    prepare_grid<Shape>();
    scatter<Shape, ScatterMomentum>();
    ddmp_hand_on<Shape>(lane::mass, 4, true);
    // Stress first, from the velocity at the start of the step (lanes 4–6).
    grid_velocity_from_momentum(grid, lane::momentum, lane::force, body_info);
    ddmp_read_back<Shape>(lane::force, 3);
    impose_boundaries(lane::force);
    gather<Shape, GatherStrain>(dt);
    clear_grid_lanes(grid, lane::force, 3);
    scatter<Shape, ScatterForce>();
    add_contact_forces<Shape>();
    ddmp_hand_on<Shape>(lane::force, 3, false);
    reactions = update_grid_velocities(grid, dt, settings().gravity, body_info);
    constrain_boundaries(dt);
    ddmp_read_back<Shape>(lane::momentum, 6);
    gather<Shape, GatherMotion>(dt);
  }

  // --- Boundaries (boundary.hpp) ----------------------------------------------------------

  BoundaryPass boundary_pass(Real dt) {
    return {grid, settings().cell_size, dt, settings().gravity, &reactions, penalty_contact ? &contact : nullptr};
  }
  // After the node update: every boundary constrains its nodes and keeps its reaction.
  void constrain_boundaries(Real dt) {
    BoundaryPass pass = boundary_pass(dt);
    for (auto& b : sim.boundaries_) std::visit([&](auto& boundary) { boundary.constrain(pass); }, b);
  }
  // The boundaries' velocities on the field in lanes [lane, lane + 3), without reactions.
  void impose_boundaries(int lane) {
    BoundaryPass pass = boundary_pass(0);
    for (auto& b : sim.boundaries_) std::visit([&](auto& boundary) { boundary.impose(pass, lane); }, b);
  }

  // --- Penalty contact (rigid_contact.hpp) ----------------------------------------------

  // After a penalty body was added: contact history for every point, the default stiffness
  // per body and the contact's bound on the time step.
  void enable_penalty_contact() {
    penalty_contact = true;
    Particles& ps = particles();
    if (ps.contact_body.empty()) ps.contact_body.assign(ps.size(), -1), ps.contact_anchor.assign(ps.size(), Vec3::Zero());
    contact_materials.assign(body_info.size(), ContactMaterial{});
    for (size_t b = 0; b < body_info.size(); ++b) {
      if (body_info[b].role != BodyRole::deformable) continue;
      const Real c2 = std::visit([](const auto& m) { return m.wave_speed_squared(1); }, body_info[b].model);
      contact_materials[b] = {true, default_contact_stiffness_per_mass(c2, settings().cell_size)};
    }
    contact_rate_sq = stable_contact_rate_squared(ps, contact_materials, sim.rigid_bodies_);
  }

  // The contact forces at the start of the step (positions x^n, bodies at X^n) into the
  // force lanes, f_i += S_ip f_p, point by point in order (deterministic). DDMP's weights
  // are the linear ones (shape_ddmp.hpp), so those points take the linear stencil; so do
  // CPDI1 points, whose contact paper B handles at the material point (Sec. 3.4).
  template <class Shape>
  void add_contact_forces() {
    if (!penalty_contact) return;
    update_penalty_contacts(particles(), contact_materials, sim.rigid_bodies_, sim.diagnostics_.rigid, contact);
    using Weights =
        std::conditional_t<has_smoothed_gradient<Shape>::value || uses_domain_vertices<Shape>::value, LinearShape, Shape>;
    constexpr int N = Weights::nodes_per_axis;
    const Real h = settings().cell_size;
    for (uint32_t p : contact.touching) {
      const auto st = make_stencil<Weights>(particles().position[p], stencil_half_size<Weights>(particles(), p, h), 1 / h);
      const Vec3& f = contact.force[p];
      for (int i = 0; i < N; ++i)
        for (int j = 0; j < N; ++j)
          for (int k = 0; k < N; ++k) {
            const Real w = st.w[i][0] * st.w[j][1] * st.w[k][2];
            if (!(w > 0)) continue;
            // Active: the point's own scatter stencil reaches at least these nodes.
            Real* lanes = grid.node(st.base[0] + i, st.base[1] + j, st.base[2] + k);
            for (int a = 0; a < 3; ++a) lanes[lane::force + a] += w * f[a];
          }
    }
  }

  // --- Sums, diagnostics and checks ------------------------------------------------------

  struct PassSums {
    Real kinetic = 0, strain = 0, dissipation = 0, gravity_power = 0, record_stress_volume = 0, record_volume = 0;
    Real max_speed_sq = 0, max_wave_speed_sq = 0;
  } sums;

  void absorb_tallies(bool velocity, bool position, bool gradient) {
    PassSums s;
    for (size_t bi = 0; bi < tallies.size(); ++bi) {
      const BucketTally& t = tallies[bi];
      if (t.fault != ParticleFault::none) throw_fault(t.fault, t.fault_particle);
      s.kinetic += t.kinetic;
      s.strain += t.strain;
      s.dissipation += t.dissipation;
      s.gravity_power += t.gravity_power;
      s.record_stress_volume += t.record_stress_volume;
      s.record_volume += t.record_volume;
      s.max_speed_sq = std::max(s.max_speed_sq, t.max_speed_sq);
      s.max_wave_speed_sq = std::max(s.max_wave_speed_sq, t.max_wave_speed_sq);
    }
    if (velocity) {
      sums.kinetic = domain.reduce_sum(s.kinetic);
      sums.max_speed_sq = domain.reduce_max(s.max_speed_sq);
    }
    if (position) {
      sums.gravity_power = domain.reduce_sum(s.gravity_power);
      take_cell_ranges();
    }
    if (gradient) {
      sums.strain = domain.reduce_sum(s.strain);
      sums.dissipation = domain.reduce_sum(s.dissipation);
      sums.record_stress_volume = domain.reduce_sum(s.record_stress_volume);
      sums.record_volume = domain.reduce_sum(s.record_volume);
      sums.max_wave_speed_sq = domain.reduce_max(s.max_wave_speed_sq);
    }
  }

  [[noreturn]] void throw_fault(ParticleFault fault, uint32_t p) const {
    const Particles& ps = sim.particles_;
    std::ostringstream msg;
    msg.precision(6);
    msg << "step " << sim.diagnostics_.step + 1 << " (t = " << sim.diagnostics_.time << " s): particle "
        << ps.id[p] << " of body '" << sim.bodies_[size_t(ps.body[p])].name << "' at ("
        << ps.position[p][0] << ", " << ps.position[p][1] << ", " << ps.position[p][2] << ") m ";
    switch (fault) {
      case ParticleFault::not_finite: msg << "has a NaN or infinite velocity, position or stress"; break;
      case ParticleFault::inverted:
        msg << "is inverted or crushed (J = " << ps.deformation[p].determinant() << " <= "
            << settings().min_jacobian << ")";
        break;
      case ParticleFault::left_grid: msg << "left the grid (more than " << max_cell_coord << " cells from the origin)"; break;
      case ParticleFault::none: break;
    }
    msg << "; try a smaller cfl or time step";
    throw NumericalError(msg.str());
  }

  Vec3 centre_of_mass(size_t body) const {
    Vec3 mx = Vec3::Zero();
    Real m = 0;
    const auto& runs = buckets.runs();
    for (size_t r = 0; r < runs.size(); ++r)
      if (size_t(runs[r].body) == body) mx += run_tallies[r].mass_position, m += run_tallies[r].mass;
    return m > 0 ? Vec3(mx / m) : Vec3::Zero();
  }

  // ψ of deformable particle p (J/m³ of reference volume), with its history if its model has one.
  Real energy_density(size_t p) const {
    const Particles& ps = sim.particles_;
    const BodyInfo& body = body_info[size_t(ps.body[p])];
    return std::visit([&](const auto& m) {
      constexpr size_t count = history_size<std::decay_t<decltype(m)>>;
      Real history[count > 0 ? count : 1] = {};
      for (size_t k = 0; k < count; ++k) history[k] = ps.history[body.history_columns[k]].values[p];
      return strain_energy_density(m, ps.deformation[p], ps.stress[p], history);
    }, body.model);
  }

  // Speeds, energy and body centres from the particles as they are now: at the start, and
  // after a caller changed them through mutable_particles() before the first step.
  bool refresh_needed = true;
  void refresh() {
    const Particles& ps = sim.particles_;
    max_speed = 0;
    max_wave_speed = 0;
    initial_energy = 0;
    const size_t nb = body_info.size();
    for (size_t b = 0; b < nb; ++b) {
      if (body_info[b].role == BodyRole::deformable)
        max_wave_speed = std::max(max_wave_speed,
            std::sqrt(std::visit([](const auto& m) { return m.wave_speed_squared(1); }, body_info[b].model)));
      else
        max_speed = std::max(max_speed, body_info[b].velocity.norm());
    }
    for (const auto& r : sim.diagnostics_.rigid) max_speed = std::max(max_speed, r.velocity.norm());
    std::vector<Vec3> mx(nb, Vec3::Zero());
    std::vector<Real> mass(nb, 0);
    for (size_t p = 0; p < ps.size(); ++p) {
      const size_t b = size_t(ps.body[p]);
      mx[b] += ps.mass[p] * ps.position[p];
      mass[b] += ps.mass[p];
      if (body_info[b].role != BodyRole::deformable) continue;
      max_speed = std::max(max_speed, ps.velocity[p].norm());
      initial_energy += Real(0.5) * ps.mass[p] * ps.velocity[p].squaredNorm() + ps.volume0[p] * energy_density(p);
    }
    initial_centre.assign(nb, Vec3::Zero());
    for (size_t b = 0; b < nb; ++b) if (mass[b] > 0) initial_centre[b] = mx[b] / mass[b];
    refresh_needed = false;
  }

  // cfl · h/(c + |v|); with penalty contact cfl · 2/√(ω² + κ/m), ω = 2(c + |v|)/h the
  // grid's highest frequency and κ/m the largest of a contact spring (rigid_contact.hpp).
  Real stable_time_step() {
    if (refresh_needed) refresh();
    const Real speed = max_wave_speed + max_speed;
    if (contact_rate_sq > 0) {
      const Real rate = speed / settings().cell_size;
      return settings().cfl / std::sqrt(rate * rate + contact_rate_sq / 4);
    }
    return speed > 0 ? settings().cfl * settings().cell_size / speed : std::numeric_limits<Real>::infinity();
  }
};


}  // namespace latmpm::mpm
