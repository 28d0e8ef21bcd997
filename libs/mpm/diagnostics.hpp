// What one step reports: the quantities the run's series output needs (issue 5,
// "Diagnostics"). Forces in N, energies in J, SI throughout.
#pragma once
#include <cstdint>
#include <vector>

#include "mpm/real.hpp"
#include "mpm/rigid_body.hpp"

namespace latmpm::mpm {

struct StepDiagnostics {
  int64_t step = 0;     // steps completed (1 after the first step)
  Real time = 0;        // s, at the end of the step
  Real dt = 0;          // s, this step's time step
  Real stable_dt = 0;   // s, cfl · h / max(c + |v|) at the start of this step

  // Per body, indexed like Simulation::bodies().
  // Displacement: driven bodies ∫ v dt, fixed bodies 0, deformable bodies the change of
  // their centre of mass (m).
  std::vector<Vec3> body_displacement;
  // Reaction: for fixed and driven bodies the force their constraint applies to the rest of
  // the model, Σ over their constrained nodes of  (m_i v_prescribed − m_i v_i − dt f_i)/dt,
  // f_i the nodal internal + gravity force (N). A plate compressing a specimen downwards
  // has a negative z reaction; the load the specimen carries is its negation. For a
  // deformable body, the same sum over the nodes its held points reach (BodySettings::
  // hold_tag); zero when it holds none.
  std::vector<Vec3> reaction;

  Real kinetic_energy = 0;  // ½ Σ m v² over deformable points, J
  Real strain_energy = 0;   // Σ V0 ψ over deformable points, J (linear elastic: its stress work)
  // Energy the materials dissipated since the start, J: Σ V0 × the plastic work per
  // reference volume of J2 points (Paper B Eq. 13's Σ Δα y(α)); zero for elastic models.
  Real plastic_dissipation = 0;
  // Work done on the deformable material by reactions of driven bodies and by gravity,
  // accumulated since the start, J. Energy balance: kinetic + strain ≈ initial + work
  // (minus what PIC damping and contact dissipate).
  Real external_work = 0;
  Real max_speed = 0;       // max |v_p| over deformable points after the step, m/s

  // Geometric rigid bodies (rigid_body.hpp), indexed like Simulation::rigid_bodies(): state
  // at the end of the step (reaction: force of the body on the model during the step).
  std::vector<RigidBodyState> rigid;

  // Energy accounting (docs/solver.md, "Energy"). constraint_work: ∫ Σ r · v dt of the
  // point-defined fixed and driven bodies (zero for a fixed base); gravity_work: gravity's
  // work on the deformable material; rigid_energy: Σ kinetic + potential energy of the free
  // rigid bodies; energy_error: (kinetic + strain + plastic_dissipation + rigid_energy + contact_energy +
  // friction_dissipation + blend_dissipation + transfer_dissipation) − their initial value −
  // constraint_work − gravity_work − work of driven rigid bodies. Zero for an exact
  // scheme; what is left is the transfers' and the time integration's own error (MPM's
  // grid-to-particle projection dissipates a little, so it drifts negative).
  Real constraint_work = 0;
  Real gravity_work = 0;
  Real rigid_energy = 0;
  // Penalty bodies (rigid_contact.hpp): contact_energy, held in their contact springs now;
  // friction_dissipation, lost to their Coulomb friction since the start. Their work is
  // their own power f·V, so both enter energy_error beside the material's energies.
  Real contact_energy = 0;
  Real friction_dissipation = 0;
  // Kinetic energy the FLIP/PIC velocity blend (Settings::flip_blend) removed since the start:
  // Σ over steps and points of ½ m (|v_FLIP|² − |v|²), v_FLIP the pure FLIP update. A
  // numerical dissipation of the scheme (zero for flip = 1), kept apart from the physical
  // ones (plastic, friction), J.
  Real blend_dissipation = 0;
  // Energy the FLIP update's grid-to-point projection lost since the start: Σ over steps of
  // Σ_I m_I |Δv_I|² − Σ_p m_p |Σ_I S_Ip Δv_I|², the grid's velocity increments against what
  // the points receive of them (≥ 0 each step; step_stages.cpp, absorb_tallies, derives it).
  // A numerical dissipation of the transfer, largest where the increments vary within a
  // stencil (impacts, contact forces on a few points, ringing at the grid's shortest
  // wavelengths), kept apart like the blend's, J.
  Real transfer_dissipation = 0;
  // Kinetic energy grid contact's rule (field_contact.hpp) took out of the nodes since the
  // start: at each contact node Σ_K ½ m_K (|v*_K|² − |v_K|²), the fields' free velocities
  // against the corrected ones, J. A nodal estimate, not in energy_error: it overcounts the
  // points' loss 4–9× (the head-on bars, docs/contact.md "Energy"), from nodes where a field
  // has little mass (½ Δt² |f|²/m_K).
  Real grid_contact_dissipation = 0;
  Real energy_error = 0;
};

}  // namespace latmpm::mpm
