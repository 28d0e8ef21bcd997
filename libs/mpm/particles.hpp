// Particle state as a structure of arrays: one array per quantity, no per-particle
// objects. The solver keeps particles sorted by grid bucket for locality, so the index of a
// particle changes during a run; `id` is its index in the original PointSet.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "mpm/real.hpp"

namespace latmpm::mpm {

// One history variable of a material model (material_history.hpp), per particle: every
// particle has the column, particles of other models keep `initial`.
struct HistoryColumn {
  std::string name;
  Real initial = 0;
  std::vector<Real> values;
  bool derived = false;  // HistoryVariable::derived
};

// A CPDI1 particle's reference domain (shape_cpdi.hpp), column α for vertex α: rows 0–2
// the offset X_α − X_p (m), row 3 w_α = ∫Q_α dV / V0, rows 4–6 g_α = ∫Grad Q_α dV / V0 (1/m).
using CpdiParticleDomain = Eigen::Matrix<Real, 7, 8>;

// The arrays below are listed once more, in particle_fields.hpp: everything that handles
// every field (resize, permute, checkpoint, memory) goes through that list.
struct Particles {
  std::vector<Vec3> position;        // m
  // ParticleReal (real.hpp): float in the mixed-precision build, double otherwise.
  std::vector<ParticleVec3> velocity;        // m/s
  std::vector<ParticleReal> mass;            // kg (density × mass scaling × initial volume)
  std::vector<ParticleReal> volume0;         // m³, initial volume V0 (current volume = J · V0)
  std::vector<ParticleMat3> deformation;     // F, dimensionless
  std::vector<ParticleSymTensor> stress;     // Cauchy stress, Pa, Voigt xx yy zz yz xz xy
  std::vector<ParticleVec3> half_size0;      // m, initial GIMP particle-domain half-lengths (a
                                             // point set's zero half-size becomes cell_size / (2 ppc))
  std::vector<int32_t> body;         // index into Simulation::bodies()
  std::vector<uint32_t> id;          // index in the PointSet the particles came from
  std::vector<uint8_t> flags;        // bit flags below
  // Penalty contact history (rigid_contact.hpp), empty unless a rigid body uses it: the
  // rigid body a point is attached to (−1: none) and its attachment point x_A in that
  // body's frame (m, x_A − the body's displacement).
  std::vector<int32_t> contact_body;
  std::vector<Vec3> contact_anchor;
  // CPDI1 domains (shape_cpdi.hpp), empty unless the run's shape function is cpdi1.
  std::vector<CpdiParticleDomain> cpdi_domain;
  // Grid contact's velocity field of each point (field_contact.hpp), empty unless the run
  // has multi-field contact.
  std::vector<uint8_t> contact_field;
  // Where each point started (X_p, m), empty unless the null-space filter anchors its fit to
  // the reference map (NullSpaceFilter::reference_map).
  std::vector<Vec3> reference_position;
  // DDMP's stabilization stress σ_s (Pa, Voigt as stress; ddmp_stabilization.hpp), empty
  // unless the run's DDMP is stabilized (Settings::ddmp_stabilization > 0).
  std::vector<ParticleSymTensor> ddmp_stabilization_stress;
  // Material history, one column per variable the run's models declare (material_history.hpp).
  std::vector<HistoryColumn> history;

  static constexpr uint8_t record_flag = 1;  // carries the record tag
  static constexpr uint8_t held_flag = 2;    // deformable point whose stencil nodes are held at rest

  size_t size() const { return position.size(); }
  Real jacobian(size_t p) const { return deformation[p].cast<Real>().determinant(); }
  Real von_mises_stress(size_t p) const { return von_mises(stress[p]); }
  // Applies the same permutation (new index i takes old index order[i]) to every array.
  void permute(const std::vector<uint32_t>& order);
  // Every array to n particles, new ones at the registry's fill values.
  void resize(size_t n);
  // The history column of that name, or nullptr.
  const HistoryColumn* history_column(const std::string& name) const;
};

}  // namespace latmpm::mpm
