// Rigid bodies as geometry, not particles: a box or a half-space that is driven at a
// prescribed velocity (a compressing plate), fixed (a support: an anvil, a base), or free,
// with a mass, an initial velocity and gravity (paper A Sec. 6: the 10 kg impact flyer at
// 2 m/s). They need no 1e6-density particles and carry no mass to the grid.
//
// Coupling through the grid, no-slip as in paper A (its heavy-particle plates stick too):
// after the explicit grid update, every node with mass whose support (the cube of one cell
// around it) overlaps the body's current geometry takes the body's velocity — the nodes a
// heavy-particle plate of the same extent would touch, so the two load a specimen alike
// (a node merely inside the geometry would let the surface material slip away from the
// body between node planes: the contact force then sags by tens of percent). The force on the body is the momentum change that
// imposes, r = Σ m_i (V − v_i)/dt over those nodes (v_i the node's velocity after the free
// update, so r already nets out the node's internal force and gravity) — the same reaction
// the point-defined fixed and driven bodies report (docs/solver.md, "Boundary conditions").
//
// Alternatively a body couples by penalty contact of the material points against its surface
// with Coulomb friction (paper B Sec. 2.1, Ding & Schroeder; rigid_contact.hpp): its nodes are
// then left free, the points it touches get a force, and R^n is the sum of those forces.
//
// Order within a step n (docs/solver.md, "Rigid bodies"): the grid update uses V^n and the
// geometry at X^n and yields the reaction R^n (force of the body on the model); then a free
// body integrates M dV/dt = −R^n + M g:
//   V^{n+1} = V^n + dt (g − R^n/M),   X^{n+1} = X^n + dt (V^n + V^{n+1})/2,
// which is exact for constant acceleration (a body under gravity alone falls exactly).
#pragma once
#include <string>
#include <vector>

#include "mpm/motion_schedule.hpp"
#include "mpm/real.hpp"

namespace latmpm::mpm {

class SparseGrid;

enum class RigidShape {
  box,         // axis-aligned box [box_min, box_max] at t = 0, translated with the body
  half_space,  // {x : (x − plane_point)·plane_normal ≤ 0}: the solid lies behind the plane,
               // the normal points out of the body (toward the specimen)
};

enum class RigidMotion {
  driven,  // moves at `velocity` whatever the force on it
  free,    // M dV/dt = force from the specimen + M g (if `gravity`); `velocity` is V(0)
  fixed,   // stays where it is: a support (its `velocity` must be zero); its reaction is recorded
  scheduled,  // follows `schedule` (velocity against time, motion_schedule.hpp) whatever the
              // force on it: loading, holding and unloading in one run
};

// How a body acts on the material.
enum class RigidCoupling {
  no_slip,  // the grid nodes its support overlaps take its velocity (above); the default
  penalty,  // penalty contact of the points against its surface, Coulomb friction (rigid_contact.hpp)
};

// Penalty contact: what of a point touches the surface (rigid_contact.hpp).
enum class ContactReach {
  domain,  // its domain's face: the surface offset outward by the point's half-sizes; the default
  point,   // the material point itself (paper B Sec. 2.1: "a penetration of the material point's
           // position"; Sec. 3.4: handled for the material points, not the CPDI vertices)
};

// Their names in scenes (names.cpp: one table each); parse_* throws InputError for another.
std::string to_string(RigidShape shape);
std::string to_string(RigidMotion motion);
std::string to_string(RigidCoupling coupling);
std::string to_string(ContactReach reach);
std::vector<std::string> contact_reach_names();
ContactReach parse_contact_reach(const std::string& name);
std::vector<std::string> rigid_shape_names();
std::vector<std::string> rigid_motion_names();
std::vector<std::string> rigid_coupling_names();
RigidShape parse_rigid_shape(const std::string& name);
RigidMotion parse_rigid_motion(const std::string& name);
RigidCoupling parse_rigid_coupling(const std::string& name);

struct RigidBodySettings {
  std::string name;
  RigidShape shape = RigidShape::box;
  Vec3 box_min = Vec3::Zero(), box_max = Vec3::Zero();          // m (box)
  Vec3 plane_point = Vec3::Zero(), plane_normal = Vec3::UnitZ();  // m, unit (half_space)
  RigidMotion motion = RigidMotion::driven;
  Vec3 velocity = Vec3::Zero();  // m/s: prescribed (driven) or initial (free); zero (fixed);
                                 // the schedule's V(0) (scheduled)
  MotionSchedule schedule;       // scheduled bodies only
  Real mass = 0;                 // kg, free bodies
  bool gravity = true;           // free bodies: Settings::gravity acts on them
  RigidCoupling coupling = RigidCoupling::no_slip;
  // Penalty contact: κ, the spring between a point and its attachment point (N/m, per point);
  // 0 takes the default m_p c²/h² of the point's material (rigid_contact.hpp).
  Real contact_stiffness = 0;
  // Penalty contact: Coulomb coefficient μ ≥ 0; 0 slides freely, infinity never slides.
  Real friction = 0;
  // Penalty contact: a point touches with its domain's face or at its position.
  ContactReach contact_reach = ContactReach::domain;
};

// Throws InputError(where, "rigid_bodies.<name>.<key>", ...) for an empty or inverted box, a
// zero normal, a free body without a positive mass, a fixed body with a non-zero velocity,
// non-finite values, a negative or non-finite contact stiffness, a negative or NaN friction
// coefficient, a scheduled body without a valid schedule (motion_schedule.hpp) or whose velocity
// is not the schedule's V(0), a schedule on a body of another motion.
void validate(const RigidBodySettings& body, const std::string& where);

// What changes during a run.
struct RigidBodyState {
  Vec3 displacement = Vec3::Zero();  // m, X − X(0)
  Vec3 velocity = Vec3::Zero();      // m/s, V
  Vec3 reaction = Vec3::Zero();      // N, force of the body on the model in the last step
  Real work = 0;                     // J, ∫ reaction · V dt: work done on the model
  Real time = 0;                     // s, the body's clock since the start (scheduled bodies)
};

// Whether the node at x (m) is coupled to the body displaced by d: its support, the open
// cube of half-width h (the cell size) around it, overlaps the body.
bool rigid_body_contains(const RigidBodySettings& body, const Vec3& displacement, const Vec3& x, Real h);
// False only if no node in the box [lo, hi] (m) can be coupled to the body: a test on the
// box's corners with a margin far above round-off, so the solver skips whole grid blocks
// far from the body and rigid_body_contains still decides every node near it.
bool rigid_body_may_reach(const RigidBodySettings& body, const Vec3& displacement, const Vec3& lo, const Vec3& hi,
                          Real h);

// After update_grid_velocities (lanes m, v_new, Δv, constraint): every node with mass, not
// held by a point-defined body (constraint lane > 0) nor claimed by another geometric body
// (lane < 0), whose support overlaps the body takes its velocity V and is claimed with
// `marker` (< 0: −(rigid index + 1)); Δv is corrected to match. Called for the bodies in
// order, a node inside two bodies goes to the first. Returns the reaction
// Σ m (V − v_new)/dt (N) per active block, 3 values a block in block order: their sum in
// that order (Domain::sum_in_order, over every process's blocks) is the body's reaction.
std::vector<Real> couple_rigid_body(SparseGrid& grid, Real h, Real dt, const RigidBodySettings& body,
                       const RigidBodyState& state, Real marker);

// The same constraint on a velocity field in lanes [lane, lane + 3) without a reaction (MUSL's
// remapped velocity, USF's start-of-step velocity).
void impose_rigid_velocity(SparseGrid& grid, Real h, int lane, const RigidBodySettings& body,
                           const RigidBodyState& state, Real marker);

// Advances a body over a step of length dt after the grid update gave its reaction (a fixed
// body stays at rest and only records it; a scheduled one takes its displacement D(t) and
// velocity V(t) from the schedule at the step's end, so it follows the schedule exactly).
void advance_rigid_body(const RigidBodySettings& body, RigidBodyState& state, const Vec3& reaction,
                        const Vec3& gravity, Real dt);

// The largest speed the body is given (m/s): |velocity|, or the schedule's largest (scheduled).
Real prescribed_max_speed(const RigidBodySettings& body);

// Kinetic energy ½ M V² and potential energy −M g·(X − X(0)) of a free body (J); zero for
// driven and fixed bodies (their energy is not part of the model: they are a boundary condition).
Real rigid_kinetic_energy(const RigidBodySettings& body, const RigidBodyState& state);
Real rigid_potential_energy(const RigidBodySettings& body, const RigidBodyState& state, const Vec3& gravity);

}  // namespace latmpm::mpm
