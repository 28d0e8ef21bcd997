#include "mpm/boundary.hpp"

#include "mpm/checkpoint_io.hpp"
#include "mpm/grid_update.hpp"
#include "mpm/rigid_contact.hpp"

namespace latmpm::mpm {

// --- Point-defined: fixed and driven point bodies, held points ---------------------------

void PointBoundary::constrain(BoundaryPass& pass) {
  // The node update imposed the constraint on the nodes this body's points marked in P2G and
  // summed the reaction per body (grid_update.cpp).
  reaction = pass.node_reactions->force[body];
  power = pass.node_reactions->power[body];
}

void PointBoundary::advance(const BoundaryPass& pass, BoundaryLedger& ledger) {
  if (role != BodyRole::driven) return;
  displacement += pass.dt * velocity;
  ledger.external_power += power;
  ledger.constraint_power += power;
  ledger.max_speed = std::max(ledger.max_speed, velocity.norm());
}

void PointBoundary::save(CheckpointWriter& out) const {
  out.rows("displacement", std::vector<Vec3>{displacement});
  out.rows("reaction", std::vector<Vec3>{reaction});
}

void PointBoundary::load(const CheckpointReader& in) {
  displacement = in.rows<Vec3>("displacement", 1)[0];
  reaction = in.rows<Vec3>("reaction", 1)[0];
}

BoundaryReport PointBoundary::report() const {
  BoundaryReport r;
  r.name = name;
  r.role = role == BodyRole::driven ? BoundaryRole::driven : role == BodyRole::fixed ? BoundaryRole::fixed
                                                                                      : BoundaryRole::held;
  r.displacement = displacement;
  r.reaction = reaction;
  r.velocity = velocity;
  return r;
}

// --- Geometric rigid bodies, no-slip -----------------------------------------------------

namespace {
Real claim_marker(size_t index) { return -Real(index + 1); }
}  // namespace

void RigidBoundary::constrain(BoundaryPass& pass) {
  // Per block, summed in block order over every process's blocks: the one-process sum.
  const std::vector<Real> rows = couple_rigid_body(pass.grid, pass.cell_size, pass.dt, settings, state, claim_marker(index));
  std::vector<uint64_t> keys(pass.grid.block_count());
  for (size_t b = 0; b < keys.size(); ++b) keys[b] = pass.grid.key(b);
  const std::vector<Real> sum = pass.domain ? pass.domain->sum_in_order(keys, rows, 3) : sum_rows(rows, 3);
  reaction = Vec3(sum[0], sum[1], sum[2]);
}

void RigidBoundary::impose(BoundaryPass& pass, int lane) {
  impose_rigid_velocity(pass.grid, pass.cell_size, lane, settings, state, claim_marker(index));
}

namespace {
// A geometric body's part after the step: its work on the model at power `power`, then its
// motion under the reaction (rigid_body.hpp), then its energy.
void advance_rigid(RigidBoundary& b, Real power, const BoundaryPass& pass, BoundaryLedger& ledger) {
  ledger.external_power += power;
  // Bodies of prescribed motion are boundary conditions: their work enters the balance (a
  // fixed no-slip body's is zero; a fixed penalty body's is its springs' work on the points).
  if (b.settings.motion != RigidMotion::free) ledger.prescribed_work += pass.dt * power;
  advance_rigid_body(b.settings, b.state, b.reaction, pass.gravity, pass.dt);
  ledger.energy += rigid_kinetic_energy(b.settings, b.state) + rigid_potential_energy(b.settings, b.state, pass.gravity);
  ledger.max_speed = std::max(ledger.max_speed, b.state.velocity.norm());
}
}  // namespace

void RigidBoundary::advance(const BoundaryPass& pass, BoundaryLedger& ledger) {
  advance_rigid(*this, reaction.dot(state.velocity), pass, ledger);
}

void RigidBoundary::save(CheckpointWriter& out) const {
  out.rows("displacement", std::vector<Vec3>{state.displacement});
  out.rows("velocity", std::vector<Vec3>{state.velocity});
  out.rows("reaction", std::vector<Vec3>{state.reaction});
  out.scalar("work", state.work);
  // Its clock (only a scheduled body reads it; the other kinds' checkpoints stay as they were).
  if (settings.motion == RigidMotion::scheduled) out.scalar("time", state.time);
}

void RigidBoundary::load(const CheckpointReader& in) {
  state.displacement = in.rows<Vec3>("displacement", 1)[0];
  state.velocity = in.rows<Vec3>("velocity", 1)[0];
  state.reaction = in.rows<Vec3>("reaction", 1)[0];
  state.work = in.scalar("work");
  if (settings.motion == RigidMotion::scheduled) state.time = in.scalar("time");
  reaction = state.reaction;
}

BoundaryReport RigidBoundary::report() const {
  BoundaryReport r;
  r.name = settings.name;
  r.role = settings.motion == RigidMotion::driven || settings.motion == RigidMotion::scheduled ? BoundaryRole::driven
           : settings.motion == RigidMotion::fixed ? BoundaryRole::fixed
                                                   : BoundaryRole::free;
  r.displacement = state.displacement;
  r.reaction = state.reaction;
  r.velocity = state.velocity;
  r.kinetic_energy = rigid_kinetic_energy(settings, state);
  return r;
}

// --- Geometric rigid bodies, penalty contact ---------------------------------------------

void PenaltyBoundary::constrain(BoundaryPass& pass) {
  // Its push is the sum of its points' contact forces from the contact stage.
  reaction = Vec3::Zero() + pass.contact->reaction[index];
  spring_energy = pass.contact->spring_energy[index];
  friction_dissipation += pass.contact->friction_work[index];
}

void PenaltyBoundary::advance(const BoundaryPass& pass, BoundaryLedger& ledger) {
  // Its power is its own, f·V, as for a no-slip body: the work it does on its springs, which
  // pass it on to the points less what they hold and what friction dissipates
  // (rigid_contact.hpp, ContactForces). Paper B measures f_i V the same way.
  advance_rigid(*this, reaction.dot(state.velocity), pass, ledger);
  ledger.contact_energy += spring_energy;
  ledger.friction_dissipation += friction_dissipation;
}

void PenaltyBoundary::save(CheckpointWriter& out) const {
  RigidBoundary::save(out);
  out.scalar("friction_dissipation", friction_dissipation);
}

void PenaltyBoundary::load(const CheckpointReader& in) {
  RigidBoundary::load(in);
  friction_dissipation = in.scalar("friction_dissipation");
}

const RigidBoundary* as_rigid(const Boundary& boundary) {
  if (const auto* r = std::get_if<RigidBoundary>(&boundary)) return r;
  return std::get_if<PenaltyBoundary>(&boundary);
}

RigidBoundary* as_rigid(Boundary& boundary) {
  return const_cast<RigidBoundary*>(as_rigid(static_cast<const Boundary&>(boundary)));
}

std::string checkpoint_name(const Boundary& boundary) {
  if (const auto* p = std::get_if<PointBoundary>(&boundary)) return "point." + p->name;
  return "rigid." + as_rigid(boundary)->settings.name;
}

}  // namespace latmpm::mpm
