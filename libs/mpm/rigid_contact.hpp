// Penalty contact of material points against the surface of a geometric rigid body, with
// Coulomb friction (paper B Sec. 2.1, after Ding & Schroeder; docs/solver.md, "Penalty
// contact"). Per point, with its domain's reach r_p beyond its position (the material's
// surface, not the point, touches the body; r_p = 0 for a body with ContactReach::point,
// paper B's contact at the material point):
//   - it is in contact while it penetrates the body's surface offset outward by r_p; at
//     first contact its attachment point x_A is the closest point of that offset surface;
//   - while in contact the body pushes it with f = κ (x_A − x_p): the normal part
//     f_n = κ d (d the penetration depth) and a tangential part from the anchor's
//     tangential offset, the stretched friction spring;
//   - when |f_t| > μ f_n, the anchor is relaxed toward the closest point until
//     |f_t| = μ f_n (the point slides, the force lies on the friction cone);
//   - contact ends when the point leaves the surface.
// The attachment point moves with the body (bodies translate only: it is kept in the body's
// frame, Particles::contact_anchor). The force acts on the grid as an external force mapped
// with the point's shape functions; its opposite acts on the body. One contact per point: a
// point attached to one body ignores the others until it leaves it.
#pragma once
#include <vector>

#include "mpm/contact_spread.hpp"
#include "mpm/particles.hpp"
#include "mpm/rigid_body.hpp"

namespace latmpm::mpm {

// Where a point stands against a body's surface.
struct ContactProbe {
  bool penetrates = false;
  Vec3 normal = Vec3::Zero();  // outward unit normal of the surface nearest the point
  Real depth = 0;              // m, > 0: how far the point's domain lies inside the body
};

// The probe of a point at x whose domain has the half-sizes `half_size` (m) against `body`
// displaced by `displacement`: a half-space's plane moved out by Σ |n_a| half_a, a box grown
// by the half-sizes (the exact Minkowski sums with the point's box domain). In a box the
// nearest face decides the normal.
ContactProbe probe_contact(const RigidBodySettings& body, const Vec3& displacement, const Vec3& x,
                           const Vec3& half_size);

// One point's contact law for one step: from its attachment point (world, m) and probe,
// the force on it (N) and the new attachment point. `friction` may be infinite (sticks).
struct ContactForce {
  Vec3 force = Vec3::Zero();
  Vec3 anchor = Vec3::Zero();
  bool sliding = false;  // the friction cone limited the tangential force
  // Energy (J): stored in the spring after the relaxation, ½ |f|²/κ; dissipated by the
  // relaxation, |f_t| · slip with slip = (|f_t trial| − |f_t|)/κ the anchor's move along the
  // surface (the return mapping's plastic work, backward Euler: the force at the step's end).
  Real spring_energy = 0;
  Real friction_work = 0;
};
ContactForce penalty_contact_force(const Vec3& anchor, const Vec3& x, const ContactProbe& probe, Real stiffness,
                                   Real friction);

// The default contact stiffness per unit point mass, c²/h² (1/s²) with c the dilatational
// wave speed of the point's material at rest, after mass scaling: κ_p = m_p c²/h². The
// penalty spring's frequency is then half the grid's highest (2c/h), so it lowers the
// stable step by at most 1/√(1 + 1/4) (stable_contact_rate_squared).
Real default_contact_stiffness_per_mass(Real wave_speed_squared, Real cell_size);

// Per point body of the simulation: whether its points take part in contact (deformable
// bodies) and its default stiffness per mass (1/s²).
struct ContactMaterial {
  bool deformable = false;
  Real stiffness_per_mass = 0;
};

// What a contact pass leaves: per point its force (N, zero when not in contact), the points
// in contact in ascending order, and per rigid body the sum of its points' forces — the
// force of the body on the model (N; zero for no-slip bodies) —, the energy its springs hold
// (J) and the energy its friction dissipated in this pass (J).
//
// Energy: the body does work f·V on its springs (the anchors move with it); the springs pass
// f·v_p to the points, keep ½|f|²/κ and lose the friction's part when an anchor slides:
// ∫ f·V dt = ∫ f·v_p dt + spring energy + friction work (docs/solver.md, "Energy").
struct ContactForces {
  std::vector<Vec3> force;
  std::vector<uint32_t> touching;
  std::vector<Real> touching_spring, touching_friction;  // each touching point's terms, in its order
  std::vector<Vec3> reaction;
  std::vector<Real> spring_energy;
  std::vector<Real> friction_work;
};

// Updates every deformable point's contact with the penalty bodies at the points' and
// bodies' current positions (history in ps.contact_body / contact_anchor, which must be
// sized) and fills `out`. Deterministic for any thread count.
void update_penalty_contacts(Particles& ps, const std::vector<ContactMaterial>& materials,
                             const std::vector<RigidBodySettings>& bodies,
                             const std::vector<RigidBodyState>& states, ContactForces& out);

// reaction, spring_energy and friction_work of `out` as update_penalty_contacts adds them
// (per chunk of points in order, then chunk by chunk) from every touching point's record,
// the records in the one-process particle order (contact_spread.hpp): the one-process sums
// on several processes.
void contact_sums_in_order(const std::vector<ContactSpread>& spreads, size_t bodies, ContactForces& out);

// The largest κ_p/m_p over the points that may touch a penalty body (1/s²): the square of
// the highest frequency a penalty spring gives a point. Zero without penalty bodies.
// The explicit step then obeys dt ≤ 2/√(ω_grid² + κ/m), ω_grid = 2(c + |v|)/h
// (Simulation::stable_time_step).
Real stable_contact_rate_squared(const Particles& ps, const std::vector<ContactMaterial>& materials,
                                 const std::vector<RigidBodySettings>& bodies);

bool has_penalty_contact(const std::vector<RigidBodySettings>& bodies);

}  // namespace latmpm::mpm
