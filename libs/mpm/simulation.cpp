// The solver's step and its bookkeeping. The stages themselves are functions over the state
// (step_stages.hpp, which orders them per update scheme; transfer.hpp and grid_update.cpp
// hold the particle and node loops); this file builds the state from the points, advances
// time and turns the passes' sums into diagnostics and checks.
#include "mpm/simulation.hpp"

#include <map>

#include "mpm/cpdi_particles.hpp"
#include "mpm/gimp_domains.hpp"
#include "mpm/observers.hpp"
#include "mpm/particle_fields.hpp"
#include "mpm/step_stages.hpp"
#include "points/point_set.hpp"

namespace latmpm::mpm {

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
    // The filter changes F and takes the stress from it again: models with a stress history
    // (linear elastic's rate form, J2's be) would need their history filtered too.
    if (b.role == BodyRole::deformable && settings_.null_space_filter != NullSpaceFilter::none &&
        b.material.kind != MaterialKind::neo_hookean)
      throw InputError(where, "grid.null_space_filter",
                       "needs a material whose stress is a function of F alone (neo_hookean); body '" + name +
                           "' is " + to_string(b.material.kind));
    if (!b.velocity.allFinite()) throw InputError(where, "bodies." + name + ".velocity", "must be finite");
    if (b.hold_slip && b.hold_tag.empty())
      throw InputError(where, "bodies." + name + ".hold.slip", "needs a hold tag");
    if (!b.hold_tag.empty()) {
      const std::string field = "bodies." + name + ".hold.tag";
      if (b.role != BodyRole::deformable)
        throw InputError(where, field, "only deformable bodies hold tagged points (a " + to_string(b.role) +
                                           " body is constrained as a whole)");
      const auto tag = points.tags.find(b.hold_tag);
      const int index = points.body_index(name);
      bool any = false;
      if (tag != points.tags.end())
        for (size_t p = 0; p < points.size() && !any; ++p) any = points.body[p] == index && tag->second[p];
      if (!any) throw InputError(where, field, "no point of body '" + name + "' carries the tag '" + b.hold_tag + "'");
    }
    bodies_.push_back(b);
  }
  context_ = std::make_unique<StepContext>(settings_, bodies_, rigid_bodies_);
  context_->domain.check_supported(settings_, where);
  for (const auto& b : bodies_) {
    BodyInfo info;
    info.role = b.role;
    info.velocity = b.role == BodyRole::driven ? b.velocity : Vec3::Zero();
    info.hold_slip = b.hold_slip;
    if (b.role == BodyRole::deformable) {
      info.model = make_material_model(b.material, settings_.mass_scaling);
      info.history_columns = std::visit(
          [&](const auto& model) { return declare_history<std::decay_t<decltype(model)>>(state_.particles); }, info.model);
    }
    context_->body_info.push_back(info);
  }
  for (const auto& b : bodies_)
    if (b.role == BodyRole::driven) check_body_speed(b.velocity.norm(), where, "bodies." + b.name + ".velocity");
  // Point-defined boundaries: fixed and driven bodies, deformable bodies' held points.
  for (size_t b = 0; b < bodies_.size(); ++b)
    if (bodies_[b].role != BodyRole::deformable || !bodies_[b].hold_tag.empty())
      state_.boundaries.push_back(PointBoundary{b, bodies_[b].name, bodies_[b].role, context_->body_info[b].velocity});

  // Particles from the points.
  const size_t n = points.size();
  state_.particles.resize(n);
  const auto record = settings_.record_tag.empty() ? points.tags.end() : points.tags.find(settings_.record_tag);
  Real record_volume = 0, z_min = std::numeric_limits<Real>::infinity(), z_max = -z_min;
  for (size_t p = 0; p < n; ++p) {
    const BodySettings& b = bodies_[size_t(points.body[p])];
    state_.particles.position[p] = points.position[p];
    state_.particles.volume0[p] = points.volume[p];
    state_.particles.mass[p] = b.material.density * settings_.mass_scaling * points.volume[p];
    state_.particles.velocity[p] = (b.role == BodyRole::driven ? b.velocity : Vec3::Zero()).cast<ParticleReal>();
    state_.particles.half_size0[p] = points.domain_half_size(p).cast<ParticleReal>();
    state_.particles.body[p] = points.body[p];
    state_.particles.id[p] = uint32_t(p);
    if (!b.hold_tag.empty() && points.tags.at(b.hold_tag)[p]) state_.particles.flags[p] |= Particles::held_flag;
    if (record != points.tags.end() && record->second[p]) {
      state_.particles.flags[p] |= Particles::record_flag;
      record_volume += points.volume[p];
      z_min = std::min(z_min, points.position[p][2]);
      z_max = std::max(z_max, points.position[p][2]);
    }
  }
  // Held faces' outward directions: from each body's centroid toward its held points'.
  {
    std::vector<Vec3> all(bodies_.size(), Vec3::Zero()), held(bodies_.size(), Vec3::Zero());
    std::vector<Real> all_volume(bodies_.size(), 0), held_volume(bodies_.size(), 0);
    for (size_t p = 0; p < n; ++p) {
      const size_t b = size_t(points.body[p]);
      all[b] += points.volume[p] * points.position[p];
      all_volume[b] += points.volume[p];
      if (state_.particles.flags[p] & Particles::held_flag) held[b] += points.volume[p] * points.position[p], held_volume[b] += points.volume[p];
    }
    for (size_t b = 0; b < bodies_.size(); ++b) {
      if (!(held_volume[b] > 0)) continue;
      const Vec3 d = held[b] / held_volume[b] - all[b] / all_volume[b];
      if (d.norm() > 1e-9 * settings_.cell_size) context_->body_info[b].hold_outward = d.normalized();
      else if (bodies_[b].hold_slip)
        throw InputError(where, "bodies." + bodies_[b].name + ".hold.slip",
                         "the held points have no face direction (their centroid is the body's); clamp them instead");
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
      if (!(std::abs(state_.particles.position[p][a] / settings_.cell_size) < max_cell_coord))
        throw InputError(where, "points", "point " + std::to_string(p) + " lies more than " +
                                              std::to_string(max_cell_coord) + " cells from the origin");

  if (settings_.null_space_filter == NullSpaceFilter::reference_map)
    state_.particles.reference_position = state_.particles.position;
  // DDMP stabilized (validate() has refused the forms without it): each body's moduli, σ_s per point.
  if (settings_.shape_function == ShapeFunctionKind::ddmp && settings_.ddmp_stabilization > 0) {
    for (size_t b = 0; b < bodies_.size(); ++b)
      if (bodies_[b].role == BodyRole::deformable)
        context_->body_info[b].ddmp_stabilization =
            ddmp_stabilization_moduli(bodies_[b].material, settings_.ddmp_stabilization);
    state_.particles.ddmp_stabilization_stress.assign(n, ParticleSymTensor::Zero());
  }
  if (settings_.field_contact.enabled)  // points in field order: Particles::contact_field
    context_->grid_fields = make_contact_fields(settings_.field_contact, settings_.mass_scaling, points, bodies_,
                                                state_.particles.contact_field, where);
  if (settings_.shape_function == ShapeFunctionKind::cpdi1)
    set_cpdi_domains(state_.particles, points, bodies_, settings_.cell_size, where);
  // Fixed point bodies: their nodes marked once, their points out of the step, where that
  // gives the same nodes (fixed_body_nodes.hpp says where not).
  if (settings_.mark_fixed_bodies_once && !settings_.field_contact.enabled &&
      settings_.shape_function != ShapeFunctionKind::cpdi1 && context_->domain.process_count() == 1)
    for (size_t b = 0; b < bodies_.size(); ++b)
      if (bodies_[b].role == BodyRole::fixed) context_->body_info[b].marked_once = true;
  if (settings_.shape_function == ShapeFunctionKind::cpgimp && settings_.scheme == UpdateScheme::usl)
    refuse_wide_cpgimp_domains(state_.particles, bodies_, settings_.cell_size, where);

  state_.diagnostics.body_displacement.assign(bodies_.size(), Vec3::Zero());
  state_.diagnostics.reaction.assign(bodies_.size(), Vec3::Zero());
  refresh_carried(state_, *context_);
  state_.diagnostics.stable_dt = stable_time_step();
  // The built-in observers (observers.hpp): the first to see each step.
  observers_.push_back(BodiesApartCheck(*this));
}

Simulation::~Simulation() = default;

Particles& Simulation::mutable_particles() {
  context_->refresh_needed = true;
  context_->fixed_body_nodes.ready = false;  // the caller may move a fixed body's points
  state_.needs_sort = true;
  return state_.particles;
}

void Simulation::add_observer(Observer observer) { observers_.push_back(std::move(observer)); }

// A body faster than the material's dilatational wave speed shocks the material ahead of it:
// no elastic model here represents that, and the constraint then crushes the points between
// it and other bodies to J ≈ 0 while its huge work keeps the runaway-energy check quiet
// (measured: a plate at 1000 m/s through a column, c = 58 m/s, ran to the end). Refused.
void Simulation::check_body_speed(Real speed, const std::string& where, const std::string& field) const {
  Real c = std::numeric_limits<Real>::infinity();
  std::string slowest;
  for (size_t b = 0; b < bodies_.size(); ++b)
    if (bodies_[b].role == BodyRole::deformable) {
      const Real cb = std::sqrt(std::visit([](const auto& m) { return m.wave_speed_squared(1); }, context_->body_info[b].model));
      if (cb < c) c = cb, slowest = bodies_[b].name;
    }
  if (speed >= c) {
    std::ostringstream msg;
    msg << speed << " m/s is not below the dilatational wave speed of body '" << slowest << "' (" << c
        << " m/s, after mass scaling): the material ahead would be shocked, which the elastic models cannot "
           "represent; use a speed well below it (quasi-static loading: under 1 %)";
    throw InputError(where, field, msg.str());
  }
}

void Simulation::add_rigid_body(const RigidBodySettings& body) {
  const std::string where = "rigid_bodies." + body.name;
  if (state_.diagnostics.step > 0) throw InputError(where, "", "rigid bodies are added before the first step");
  for (const auto& b : rigid_bodies_)
    if (b.name == body.name) throw InputError(where, "", "is given twice");
  validate(body, "scene");
  if (body.coupling == RigidCoupling::penalty && std::holds_alternative<ContactFields>(context_->grid_fields))
    throw InputError(where, "contact", "penalty contact with rigid bodies does not run with grid contact yet; use no-slip");
  check_body_speed(prescribed_max_speed(body), "scene",
                   where + (body.motion == RigidMotion::scheduled ? ".schedule" : ".velocity"));
  rigid_bodies_.push_back(body);
  RigidBodyState state;
  state.velocity = body.velocity;
  state_.carried.initial_rigid_energy += rigid_kinetic_energy(body, state);
  RigidBoundary rigid{rigid_bodies_.size() - 1, body, state};
  if (body.coupling == RigidCoupling::penalty)
    state_.boundaries.push_back(PenaltyBoundary{rigid});
  else
    state_.boundaries.push_back(rigid);
  refresh_rigid_states();
  state_.diagnostics.rigid_energy = state_.carried.initial_rigid_energy;
  context_->refresh_needed = true;  // its speed enters the stable time step
  if (body.coupling == RigidCoupling::penalty) enable_penalty_contact(state_, *context_);
}

void Simulation::refresh_rigid_states() {
  state_.diagnostics.rigid.clear();
  for (const auto& b : state_.boundaries)
    if (const RigidBoundary* r = as_rigid(b)) state_.diagnostics.rigid.push_back(r->state);
}

std::vector<BoundaryReport> Simulation::boundary_reports() const {
  std::vector<BoundaryReport> out;
  for (const auto& b : state_.boundaries) {
    out.push_back(std::visit([](const auto& boundary) { return boundary.report(); }, b));
    if (const RigidBoundary* r = as_rigid(b))
      out.back().potential_energy = rigid_potential_energy(r->settings, r->state, settings_.gravity);
  }
  return out;
}

const std::vector<Vec3>& Simulation::contact_forces() const { return context_->contact.force; }

Real Simulation::stable_time_step() const { return mpm::stable_time_step(state_, *context_); }

Real Simulation::next_time_step() const {
  const Real stable = stable_time_step();
  if (settings_.fixed_time_step > 0) {
    // The explicit limit is CFL number 1: dt ≤ h / max(c + |v|).
    const Real limit = stable / settings_.cfl;
    if (settings_.fixed_time_step > limit) {
      std::ostringstream msg;
      msg << "step " << state_.diagnostics.step + 1 << " (t = " << state_.diagnostics.time << " s): the fixed time step "
          << settings_.fixed_time_step << " s exceeds the stable limit "
          << (context_->penalty_contact ? "2/sqrt((2(c+|v|)/h)^2 + contact stiffness/point mass)" : "h/(c+|v|)")
          << " = " << limit
          << " s; use a smaller time step or the automatic one";
      throw NumericalError(msg.str());
    }
    return settings_.fixed_time_step;
  }
  return settings_.max_time_step > 0 ? std::min(stable, settings_.max_time_step) : stable;
}

const StepDiagnostics& Simulation::step() {
  advance(next_time_step());
  return state_.diagnostics;
}

void Simulation::run_until(Real end_time) {
  while (state_.diagnostics.time < end_time * (1 - 1e-12)) {
    const Real dt = std::min(next_time_step(), end_time - state_.diagnostics.time);
    advance(dt);
  }
}

void Simulation::advance(Real dt) {
  if (context_->refresh_needed) refresh_carried(state_, *context_);
  const Real stable = mpm::stable_time_step(state_, *context_);
  step_scheme(state_, *context_, dt);
  finish_step(dt, stable);
}

void Simulation::finish_step(Real dt, Real stable) {
  StepContext& c = *context_;
  CarriedState& carried = state_.carried;
  StepDiagnostics& d = state_.diagnostics;
  d.step += 1;
  d.time += dt;
  d.dt = dt;
  d.stable_dt = stable;
  for (size_t b = 0; b < bodies_.size(); ++b)
    if (bodies_[b].role == BodyRole::deformable) d.body_displacement[b] = centre_of_mass(state_, c, b) - carried.initial_centre[b];
  // The boundaries' work, motion and energy (boundary.hpp), in their order.
  BoundaryLedger ledger;
  ledger.external_power = c.sums.gravity_power;
  ledger.prescribed_work = state_.carried.driven_rigid_work;
  BoundaryPass pass = boundary_pass(state_, c, dt);
  for (auto& b : state_.boundaries) {
    std::visit([&](auto& boundary) { boundary.advance(pass, ledger); }, b);
    if (const auto* point = std::get_if<PointBoundary>(&b)) {
      d.reaction[point->body] = point->reaction;
      if (point->role == BodyRole::driven) d.body_displacement[point->body] = point->displacement;
    }
  }
  refresh_rigid_states();
  state_.carried.driven_rigid_work = ledger.prescribed_work;
  d.rigid_energy = ledger.energy;
  d.contact_energy = ledger.contact_energy;
  d.friction_dissipation = ledger.friction_dissipation;
  d.external_work += dt * ledger.external_power;
  d.constraint_work += dt * ledger.constraint_power;
  d.gravity_work += dt * c.sums.gravity_power;
  d.kinetic_energy = c.sums.kinetic;
  d.blend_dissipation += c.sums.blend_dissipation;
  d.transfer_dissipation += c.sums.transfer_dissipation;
  d.grid_contact_dissipation += c.sums.grid_contact_dissipation;
  d.strain_energy = c.sums.strain;
  d.plastic_dissipation = c.sums.dissipation;
  d.max_speed = std::sqrt(c.sums.max_speed_sq);

  carried.max_speed = std::max(d.max_speed, ledger.max_speed);
  d.energy_error = d.kinetic_energy + d.strain_energy + d.plastic_dissipation + d.rigid_energy + d.contact_energy +
                   d.friction_dissipation + d.blend_dissipation + d.transfer_dissipation - carried.initial_energy -
                   state_.carried.initial_rigid_energy - d.constraint_work - d.gravity_work -
                   state_.carried.driven_rigid_work;
  if (c.sums.max_wave_speed_sq > 0) carried.max_wave_speed = std::sqrt(c.sums.max_wave_speed_sq);

  // Penalty springs compressed at the start (points placed inside a body) release energy
  // that no work put in: the most they have held counts as available (more lenient than the
  // energy actually put in, never less).
  c.peak_contact_energy = std::max(c.peak_contact_energy, d.contact_energy);
  const Real budget = std::max(carried.initial_energy + d.external_work + c.peak_contact_energy, Real(0));
  const bool runaway = d.kinetic_energy > settings_.runaway_energy_factor * budget + settings_.runaway_energy_floor;
  if (runaway || std::abs(d.energy_error) > settings_.energy_error_factor * budget + settings_.runaway_energy_floor) {
    std::ostringstream msg;
    msg << "step " << d.step << " (t = " << d.time << " s): ";
    if (runaway)
      msg << "runaway kinetic energy " << d.kinetic_energy << " J, more than " << settings_.runaway_energy_factor;
    else
      msg << "the energy balance is off by " << d.energy_error << " J, more than " << settings_.energy_error_factor;
    msg << " x the energy put in (" << budget << " J); " << fastest_particle(state_, c) << "; try a smaller cfl or time step";
    // Every process takes this decision at the same step: the energies are sums reduced over
    // all of them (keep it so: fastest_particle is collective, and solve_run waits for all).
    throw CollectiveNumericalError(msg.str());
  }
  for (const auto& observer : observers_) observer(*this, d);
}

const Domain& Simulation::domain() const { return context_->domain; }

size_t Simulation::active_grid_blocks() const { return state_.grid.block_count(); }
size_t Simulation::grid_memory_bytes() const {
  // DDMP on the grid: its nodal σ^d / L and per-block tables beside the lanes (ddmp_grid.hpp).
  const DdmpNodalValues& d = context_->ddmp_nodal;
  return state_.grid.memory_bytes() + d.values.capacity() * sizeof(Real) +
         d.neighbours.capacity() * sizeof(d.neighbours[0]) + d.distributions.capacity() * sizeof(d.distributions[0]) +
         (d.handing.capacity() + d.sizeable_mask.capacity() + d.mass_mask.capacity() +
          d.last_find.candidates.capacity() + d.last_find.handing.capacity() + d.last_find.changed.capacity()) *
             sizeof(uint64_t);
}

size_t Simulation::particle_memory_bytes() const { return mpm::particle_memory_bytes(state_.particles); }

}  // namespace latmpm::mpm
