// The solver's step and its bookkeeping. The stages themselves live in transfer.hpp
// (particles ↔ grid) and grid_update.cpp (nodes); this file orders them per update scheme,
// keeps the particle buckets and the active grid blocks current, and turns the passes'
// sums into diagnostics and stability checks.
#include "mpm/simulation.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "core/errors.hpp"
#include "mpm/grid_update.hpp"
#include "mpm/particle_buckets.hpp"
#include "mpm/sparse_grid.hpp"
#include "mpm/transfer.hpp"
#include "points/point_set.hpp"

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

  explicit Impl(Simulation& s, int threads)
      : sim(s), arena(threads > 0 ? threads : tbb::task_arena::automatic) {}

  const Settings& settings() const { return sim.settings_; }
  Particles& particles() { return sim.particles_; }

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
      for (int i = floor_div(b.box_lo[0], bw); i <= floor_div(b.box_hi[0], bw); ++i)
        for (int j = floor_div(b.box_lo[1], bw); j <= floor_div(b.box_hi[1], bw); ++j)
          for (int k = floor_div(b.box_lo[2], bw); k <= floor_div(b.box_hi[2], bw); ++k)
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
    for (const auto& colour : buckets.colours()) {
      // Buckets of one colour are two buckets apart: their boxes never overlap.
      tbb::parallel_for(tbb::blocked_range<size_t>(0, colour.size(), 1), [&](const tbb::blocked_range<size_t>& r) {
        BucketBuffer& buffer = buffers.local();
        for (size_t c = r.begin(); c < r.end(); ++c) {
          const Bucket& b = list[colour[c]];
          buffer.attach(b);
          clear_box(b, buffer);
          scatter_bucket<Shape, Mode>(b, &buckets.runs()[b.run_begin], particles(), body_info.data(),
                                      settings().cell_size, buffer);
          add_box_to_grid(b, tables[colour[c]], grid, buffer);
        }
      });
    }
  }

  template <class Shape, class Mode>
  void gather(Real dt) {
    const auto& list = buckets.buckets();
    const GatherParameters parameters{settings().cell_size, dt, settings().flip_blend, settings().gravity,
                                      settings().min_jacobian};
    tbb::parallel_for(tbb::blocked_range<size_t>(0, list.size(), 1), [&](const tbb::blocked_range<size_t>& r) {
      BucketBuffer& buffer = buffers.local();
      for (size_t bi = r.begin(); bi < r.end(); ++bi) {
        const Bucket& b = list[bi];
        buffer.attach(b);
        copy_box_from_grid(b, tables[bi], grid, buffer);
        gather_bucket<Shape, Mode>(b, &buckets.runs()[b.run_begin], particles(), body_info.data(), parameters,
                                   buffer, tallies[bi], &run_tallies[b.run_begin]);
      }
    });
    absorb_tallies(Mode::velocity, Mode::position, Mode::gradient_lane >= 0);
  }

  // --- Schemes (Nairn 2003; Bardenhagen 2002) -------------------------------------------

  template <class Shape>
  void step_usl(Real dt) {
    prepare_grid<Shape>();
    scatter<Shape, ScatterAll>();
    reactions = update_grid_velocities(grid, dt, settings().gravity, body_info);
    gather<Shape, GatherAll>(dt);
  }

  template <class Shape>
  void step_musl(Real dt) {
    prepare_grid<Shape>();
    scatter<Shape, ScatterAll>();
    reactions = update_grid_velocities(grid, dt, settings().gravity, body_info);
    gather<Shape, GatherVelocity>(dt);
    // Map the updated particle momentum back (lanes 4–6) and take L from that velocity.
    clear_grid_lanes(grid, lane::force, 3);
    scatter<Shape, ScatterRemap>();
    grid_velocity_from_momentum(grid, lane::force, lane::force, body_info);
    gather<Shape, GatherStrainAndPosition>(dt);
  }

  template <class Shape>
  void step_usf(Real dt) {
    prepare_grid<Shape>();
    scatter<Shape, ScatterMomentum>();
    // Stress first, from the velocity at the start of the step (lanes 4–6).
    grid_velocity_from_momentum(grid, lane::momentum, lane::force, body_info);
    gather<Shape, GatherStrain>(dt);
    clear_grid_lanes(grid, lane::force, 3);
    scatter<Shape, ScatterForce>();
    reactions = update_grid_velocities(grid, dt, settings().gravity, body_info);
    gather<Shape, GatherMotion>(dt);
  }

  // --- Sums, diagnostics and checks ------------------------------------------------------

  struct PassSums {
    Real kinetic = 0, strain = 0, gravity_power = 0, record_stress_volume = 0, record_volume = 0;
    Real max_speed_sq = 0, max_wave_speed_sq = 0;
  } sums;

  void absorb_tallies(bool velocity, bool position, bool gradient) {
    PassSums s;
    for (size_t bi = 0; bi < tallies.size(); ++bi) {
      const BucketTally& t = tallies[bi];
      if (t.fault != ParticleFault::none) throw_fault(t.fault, t.fault_particle);
      s.kinetic += t.kinetic;
      s.strain += t.strain;
      s.gravity_power += t.gravity_power;
      s.record_stress_volume += t.record_stress_volume;
      s.record_volume += t.record_volume;
      s.max_speed_sq = std::max(s.max_speed_sq, t.max_speed_sq);
      s.max_wave_speed_sq = std::max(s.max_wave_speed_sq, t.max_wave_speed_sq);
    }
    if (velocity) {
      sums.kinetic = s.kinetic;
      sums.max_speed_sq = s.max_speed_sq;
    }
    if (position) {
      sums.gravity_power = s.gravity_power;
      take_cell_ranges();
    }
    if (gradient) {
      sums.strain = s.strain;
      sums.record_stress_volume = s.record_stress_volume;
      sums.record_volume = s.record_volume;
      sums.max_wave_speed_sq = s.max_wave_speed_sq;
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
    std::vector<Vec3> mx(nb, Vec3::Zero());
    std::vector<Real> mass(nb, 0);
    for (size_t p = 0; p < ps.size(); ++p) {
      const size_t b = size_t(ps.body[p]);
      mx[b] += ps.mass[p] * ps.position[p];
      mass[b] += ps.mass[p];
      if (body_info[b].role != BodyRole::deformable) continue;
      max_speed = std::max(max_speed, ps.velocity[p].norm());
      initial_energy += Real(0.5) * ps.mass[p] * ps.velocity[p].squaredNorm() +
          ps.volume0[p] * std::visit([&](const auto& m) {
            return strain_energy_density(m, ps.deformation[p], ps.stress[p]);
          }, body_info[b].model);
    }
    initial_centre.assign(nb, Vec3::Zero());
    for (size_t b = 0; b < nb; ++b) if (mass[b] > 0) initial_centre[b] = mx[b] / mass[b];
    refresh_needed = false;
  }

  Real stable_time_step() {
    if (refresh_needed) refresh();
    const Real speed = max_wave_speed + max_speed;
    return speed > 0 ? settings().cfl * settings().cell_size / speed : std::numeric_limits<Real>::infinity();
  }
};

// ------------------------------------------------------------------------------------------

Simulation::Simulation(const PointSet& points, const std::vector<BodySettings>& bodies,
                       const Settings& settings, const std::string& where)
    : settings_(settings) {
  validate(settings_, where);
  points.validate(where);
  // One BodySettings per point-set body, matched by name; order them like the point set.
  std::map<std::string, const BodySettings*> by_name;
  for (const auto& b : bodies) {
    if (by_name.count(b.name)) throw InputError(where, "bodies." + b.name, "is given twice");
    if (points.body_index(b.name) < 0)
      throw InputError(where, "bodies." + b.name, "the point set has no body of this name");
    by_name[b.name] = &b;
  }
  for (const auto& name : points.body_names) {
    const auto it = by_name.find(name);
    if (it == by_name.end()) throw InputError(where, "bodies", "no settings for body '" + name + "' of the point set");
    const BodySettings& b = *it->second;
    if (b.role == BodyRole::deformable) validate(b.material, where, "bodies." + name + ".material");
    if (!b.velocity.allFinite()) throw InputError(where, "bodies." + name + ".velocity", "must be finite");
    bodies_.push_back(b);
  }
  impl_ = std::make_unique<Impl>(*this, settings_.threads);
  for (const auto& b : bodies_) {
    BodyInfo info;
    info.role = b.role;
    info.velocity = b.role == BodyRole::driven ? b.velocity : Vec3::Zero();
    if (b.role == BodyRole::deformable) info.model = make_material_model(b.material, settings_.mass_scaling);
    impl_->body_info.push_back(info);
  }

  // Particles from the points.
  const size_t n = points.size();
  particles_.resize(n);
  const auto record = settings_.record_tag.empty() ? points.tags.end() : points.tags.find(settings_.record_tag);
  Real record_volume = 0, z_min = std::numeric_limits<Real>::infinity(), z_max = -z_min;
  for (size_t p = 0; p < n; ++p) {
    const BodySettings& b = bodies_[size_t(points.body[p])];
    particles_.position[p] = points.position[p];
    particles_.volume0[p] = points.volume[p];
    particles_.mass[p] = b.material.density * settings_.mass_scaling * points.volume[p];
    particles_.velocity[p] = b.role == BodyRole::driven ? b.velocity : Vec3::Zero();
    particles_.half_size0[p] = points.half_size[p];
    particles_.body[p] = points.body[p];
    particles_.id[p] = uint32_t(p);
    if (record != points.tags.end() && record->second[p]) {
      particles_.flags[p] |= Particles::record_flag;
      record_volume += points.volume[p];
      z_min = std::min(z_min, points.position[p][2]);
      z_max = std::max(z_max, points.position[p][2]);
    }
  }
  if (record_volume > 0) {
    const Real spacing = points.ppc > 0 ? points.cell_size / points.ppc : settings_.cell_size;
    const Real thickness = settings_.record_layer_thickness > 0 ? settings_.record_layer_thickness
                                                                 : (z_max - z_min) + spacing;
    record_area_ = record_volume / thickness;
  }
  for (size_t p = 0; p < n; ++p)
    for (int a = 0; a < 3; ++a)
      if (!(std::abs(particles_.position[p][a] / settings_.cell_size) < max_cell_coord))
        throw InputError(where, "points", "point " + std::to_string(p) + " lies more than " +
                                              std::to_string(max_cell_coord) + " cells from the origin");

  diagnostics_.body_displacement.assign(bodies_.size(), Vec3::Zero());
  diagnostics_.reaction.assign(bodies_.size(), Vec3::Zero());
  diagnostics_.stable_dt = stable_time_step();
}

Simulation::~Simulation() = default;

Particles& Simulation::mutable_particles() {
  impl_->refresh_needed = true;
  impl_->needs_sort = true;
  return particles_;
}

void Simulation::add_observer(Observer observer) { observers_.push_back(std::move(observer)); }

Real Simulation::stable_time_step() const { return impl_->stable_time_step(); }

Real Simulation::next_time_step() const {
  const Real stable = stable_time_step();
  if (settings_.fixed_time_step > 0) {
    // The explicit limit is CFL number 1: dt ≤ h / max(c + |v|).
    const Real limit = stable / settings_.cfl;
    if (settings_.fixed_time_step > limit) {
      std::ostringstream msg;
      msg << "step " << diagnostics_.step + 1 << " (t = " << diagnostics_.time << " s): the fixed time step "
          << settings_.fixed_time_step << " s exceeds the stable limit h/(c+|v|) = " << limit
          << " s; use a smaller time step or the automatic one";
      throw NumericalError(msg.str());
    }
    return settings_.fixed_time_step;
  }
  return settings_.max_time_step > 0 ? std::min(stable, settings_.max_time_step) : stable;
}

const StepDiagnostics& Simulation::step() {
  advance(next_time_step());
  return diagnostics_;
}

void Simulation::run_until(Real end_time) {
  while (diagnostics_.time < end_time * (1 - 1e-12)) {
    const Real dt = std::min(next_time_step(), end_time - diagnostics_.time);
    advance(dt);
  }
}

void Simulation::advance(Real dt) {
  auto& im = *impl_;
  const Real stable = im.stable_time_step();
  im.arena.execute([&] {
    with_shape_function(settings_.shape_function, [&](auto shape) {
      using Shape = decltype(shape);
      switch (settings_.scheme) {
        case UpdateScheme::usl: im.step_usl<Shape>(dt); break;
        case UpdateScheme::usf: im.step_usf<Shape>(dt); break;
        case UpdateScheme::musl: im.step_musl<Shape>(dt); break;
      }
    });
  });
  finish_step(dt, stable);
}

void Simulation::finish_step(Real dt, Real stable) {
  auto& im = *impl_;
  StepDiagnostics& d = diagnostics_;
  d.step += 1;
  d.time += dt;
  d.dt = dt;
  d.stable_dt = stable;
  Real power = im.sums.gravity_power;
  for (size_t b = 0; b < bodies_.size(); ++b) {
    switch (bodies_[b].role) {
      case BodyRole::deformable:
        d.body_displacement[b] = im.centre_of_mass(b) - im.initial_centre[b];
        d.reaction[b].setZero();
        break;
      case BodyRole::fixed:
        d.reaction[b] = im.reactions.force[b];
        break;
      case BodyRole::driven:
        d.body_displacement[b] += dt * bodies_[b].velocity;
        d.reaction[b] = im.reactions.force[b];
        power += im.reactions.power[b];
        break;
    }
  }
  d.external_work += dt * power;
  d.kinetic_energy = im.sums.kinetic;
  d.strain_energy = im.sums.strain;
  d.record_force = im.sums.record_volume > 0 ? record_area_ * im.sums.record_stress_volume / im.sums.record_volume : 0;
  d.max_speed = std::sqrt(im.sums.max_speed_sq);

  Real driven_speed = 0;
  for (const auto& b : im.body_info)
    if (b.role == BodyRole::driven) driven_speed = std::max(driven_speed, b.velocity.norm());
  im.max_speed = std::max(d.max_speed, driven_speed);
  if (im.sums.max_wave_speed_sq > 0) im.max_wave_speed = std::sqrt(im.sums.max_wave_speed_sq);

  const Real budget = std::max(im.initial_energy + d.external_work, Real(0));
  if (d.kinetic_energy > settings_.runaway_energy_factor * budget + settings_.runaway_energy_floor) {
    std::ostringstream msg;
    msg << "step " << d.step << " (t = " << d.time << " s): runaway kinetic energy " << d.kinetic_energy
        << " J, more than " << settings_.runaway_energy_factor << " x the energy put in (" << budget
        << " J); try a smaller cfl or time step";
    throw NumericalError(msg.str());
  }
  for (const auto& observer : observers_) observer(*this, d);
}

size_t Simulation::active_grid_blocks() const { return impl_->grid.block_count(); }
size_t Simulation::grid_memory_bytes() const { return impl_->grid.memory_bytes(); }

size_t Simulation::particle_memory_bytes() const {
  const Particles& p = particles_;
  return p.position.capacity() * sizeof(Vec3) + p.velocity.capacity() * sizeof(Vec3) +
         p.mass.capacity() * sizeof(Real) + p.volume0.capacity() * sizeof(Real) +
         p.deformation.capacity() * sizeof(Mat3) + p.stress.capacity() * sizeof(SymTensor) +
         p.half_size0.capacity() * sizeof(Vec3) + p.body.capacity() * sizeof(int32_t) +
         p.id.capacity() * sizeof(uint32_t) + p.flags.capacity() * sizeof(uint8_t);
}

// --- Stages for tests ---------------------------------------------------------------------

void Simulation::stage_particles_to_grid() {
  auto& im = *impl_;
  im.needs_sort = true;  // positions may have been set from outside
  im.arena.execute([&] {
    with_shape_function(settings_.shape_function, [&](auto shape) {
      using Shape = decltype(shape);
      im.prepare_grid<Shape>();
      im.scatter<Shape, ScatterAll>();
    });
  });
}

void Simulation::stage_grid_update(Real dt) {
  auto& im = *impl_;
  im.arena.execute([&] { im.reactions = update_grid_velocities(im.grid, dt, settings_.gravity, im.body_info); });
  im.grid_holds_velocity = true;
}

void Simulation::stage_set_grid_velocity(const std::function<Vec3(const Vec3&)>& field) {
  auto& g = impl_->grid;
  constexpr int bw = SparseGrid::block_width;
  for (size_t b = 0; b < g.block_count(); ++b) {
    const auto c = g.coord(b);
    for (int i = 0; i < bw; ++i)
      for (int j = 0; j < bw; ++j)
        for (int k = 0; k < bw; ++k) {
          Real* node = g.block(b) + SparseGrid::node_offset(i, j, k);
          const Vec3 v = field(SparseGrid::node_position(c[0] * bw + i, c[1] * bw + j, c[2] * bw + k, settings_.cell_size));
          for (int a = 0; a < 3; ++a) node[lane::momentum + a] = node[lane::force + a] = v[a];
        }
  }
  impl_->grid_holds_velocity = true;
}

void Simulation::stage_grid_to_particles(Real dt) {
  auto& im = *impl_;
  im.arena.execute([&] {
    with_shape_function(settings_.shape_function, [&](auto shape) { im.gather<decltype(shape), GatherAll>(dt); });
  });
}

Simulation::GridTotals Simulation::grid_totals() const {
  GridTotals t;
  const auto& g = impl_->grid;
  for (size_t b = 0; b < g.block_count(); ++b)
    for (int n = 0; n < SparseGrid::nodes_per_block; ++n) {
      const Real* node = g.block(b) + n * lane::count;
      t.mass += node[lane::mass];
      const Real scale = impl_->grid_holds_velocity ? node[lane::mass] : Real(1);
      for (int a = 0; a < 3; ++a) t.momentum[a] += scale * node[lane::momentum + a];
    }
  return t;
}

Simulation::Gathered Simulation::gather_from_grid() const {
  const Particles& copy = particles_;
  auto& im = *impl_;
  Gathered out;
  out.velocity.resize(copy.size());
  out.velocity_gradient.resize(copy.size());
  const Real inv_h = 1 / settings_.cell_size;
  BucketBuffer buffer;
  with_shape_function(settings_.shape_function, [&](auto shape) {
    using Shape = decltype(shape);
    constexpr int N = Shape::nodes_per_axis;
    for (size_t bi = 0; bi < im.buckets.buckets().size(); ++bi) {
      const Bucket& b = im.buckets.buckets()[bi];
      buffer.attach(b);
      copy_box_from_grid(b, im.tables[bi], im.grid, buffer);
      for (uint32_t p = b.begin; p < b.end; ++p) {
        const auto st = make_stencil<Shape>(copy.position[p], stencil_half_size<Shape>(copy, p, settings_.cell_size), inv_h);
        Vec3 v = Vec3::Zero();
        Mat3 grad = Mat3::Zero();
        for (int i = 0; i < N; ++i)
          for (int j = 0; j < N; ++j)
            for (int k = 0; k < N; ++k) {
              const Real* node = buffer.data.data() + buffer.offset(st.base[0] + i, st.base[1] + j, st.base[2] + k);
              const Vec3 vi(node[lane::momentum], node[lane::momentum + 1], node[lane::momentum + 2]);
              const Real w = st.w[i][0] * st.w[j][1] * st.w[k][2];
              const Vec3 dw(st.dw[i][0] * st.w[j][1] * st.w[k][2], st.w[i][0] * st.dw[j][1] * st.w[k][2],
                            st.w[i][0] * st.w[j][1] * st.dw[k][2]);
              v += w * vi;
              grad += vi * dw.transpose();
            }
        out.velocity[p] = v;
        out.velocity_gradient[p] = grad;
      }
    }
  });
  return out;
}

}  // namespace latmpm::mpm
