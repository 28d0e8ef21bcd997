// The particle field registry: every per-particle array of Particles, listed once. Storage
// (resize), sorting (permute), memory accounting, the checkpoint (save and restore) and the
// snapshots' extra scalars all visit this list, so a new particle field is one line here
// (and its member in particles.hpp). Material history columns (material_history.hpp) are
// visited after the fixed fields, one per history variable the run's models declare.
//
//   for_each_particle_field(ps, [](const ParticleField& f, auto& values, const auto& fill) { ... });
#pragma once
#include "mpm/particles.hpp"

namespace latmpm::mpm {

// What a checkpoint's values of a field must be, checked as they are read (Simulation::load_state;
// beyond the shape, and finiteness for reals).
enum class FieldBound {
  any,
  non_negative,        // mass, volume, half size
  body_index,          // 0 .. bodies − 1
  particle_id,         // a permutation of 0 .. particles − 1
  byte,                // 0 .. 255
  rigid_body_or_none,  // −1 (none) or 0 .. rigid bodies − 1
};

struct ParticleField {
  const char* name;  // dataset name in a checkpoint's particles group
  // Optional fields are empty unless the run needs them (penalty contact history): resize
  // and permute leave an empty one empty, a checkpoint holds it only when it is present.
  bool optional = false;
  // Shown in snapshots beside the fixed snapshot quantities (particle_snapshot.hpp).
  bool snapshot = false;
  FieldBound bound = FieldBound::any;
  // An optional field the scene's run uses and the checkpoint lacks: what the user can do.
  const char* when_missing = "the scene's run uses it, the checkpoint's run did not";
  // A field a checkpoint may lack (written before it existed): load_state derives it from
  // the points' state (a material history variable's HistoryVariable::derived).
  bool derived_when_missing = false;
};

// Calls visit(field, values, fill) for every per-particle array of ps, in a fixed order;
// `fill` is the value a new particle takes. PS is Particles or const Particles.
template <class PS, class Visit>
void for_each_particle_field(PS& ps, Visit&& visit) {
  visit(ParticleField{"position"}, ps.position, Vec3(Vec3::Zero()));
  visit(ParticleField{"velocity"}, ps.velocity, ParticleVec3(ParticleVec3::Zero()));
  visit(ParticleField{"mass", false, false, FieldBound::non_negative}, ps.mass, ParticleReal(0));
  visit(ParticleField{"volume0", false, false, FieldBound::non_negative}, ps.volume0, ParticleReal(0));
  visit(ParticleField{"deformation"}, ps.deformation, ParticleMat3(ParticleMat3::Identity()));
  visit(ParticleField{"stress"}, ps.stress, ParticleSymTensor(ParticleSymTensor::Zero()));
  visit(ParticleField{"half_size0", false, false, FieldBound::non_negative}, ps.half_size0, ParticleVec3(ParticleVec3::Zero()));
  visit(ParticleField{"body", false, false, FieldBound::body_index}, ps.body, int32_t(0));
  visit(ParticleField{"id", false, false, FieldBound::particle_id}, ps.id, uint32_t(0));
  visit(ParticleField{"flags", false, false, FieldBound::byte}, ps.flags, uint8_t(0));
  visit(ParticleField{"contact_body", true, false, FieldBound::rigid_body_or_none}, ps.contact_body, int32_t(-1));
  visit(ParticleField{"contact_anchor", true}, ps.contact_anchor, Vec3(Vec3::Zero()));
  visit(ParticleField{"cpdi_domain", true}, ps.cpdi_domain, CpdiParticleDomain(CpdiParticleDomain::Zero()));
  visit(ParticleField{"contact_field", true, false, FieldBound::byte}, ps.contact_field, uint8_t(0));
  visit(ParticleField{"reference_position", true}, ps.reference_position, Vec3(Vec3::Zero()));
  visit(ParticleField{"ddmp_stabilization_stress", true, false, FieldBound::any,
                      "the checkpoint's DDMP run was not stabilized (written before 2026-11-27 or with "
                      "grid.ddmp_stabilization = 0): resume with --set grid.ddmp_stabilization=0"},
        ps.ddmp_stabilization_stress, ParticleSymTensor(ParticleSymTensor::Zero()));
  for (auto& column : ps.history)
    visit(ParticleField{column.name.c_str(), false, true, FieldBound::any, "", column.derived},
          column.values, column.initial);
}

// Bytes the particle arrays hold (their capacity).
size_t particle_memory_bytes(const Particles& ps);

}  // namespace latmpm::mpm
