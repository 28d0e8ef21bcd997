// What a solver step contributes to the run's outputs: the series columns (issue 5,
// "Output": time, plate displacement, reactions on the driven plate and the fixed base,
// record-layer force, energies, external work) and the particle snapshot.
#pragma once
#include <Eigen/Core>
#include <vector>

#include "mpm/observers.hpp"
#include "mpm/simulation.hpp"
#include "run_output/particle_snapshot.hpp"
#include "run_output/series_writer.hpp"

namespace latmpm {

// step, time, dt, displacement, load_driven, load_fixed, load_record, kinetic_energy,
// strain_energy, external_work, max_speed. Loads are components along the loading axis
// (scene_simulation.hpp), compression positive:
//   load_driven =  Σ_driven reaction · a   (the specimen resists the plate)
//   load_fixed  = −Σ_fixed  reaction · a   (the base holds the specimen up)
//   load_record = −A σ̄_zz of the record layer (Paper A Sec. 5.1, the GIMP runs' measure)
//
// Appended after those (older readers keep working): the energy accounting
// constraint_work, gravity_work, energy_error, plastic_dissipation, contact_energy,
// friction_dissipation (mpm/diagnostics.hpp), load_average (paper B's f_a, Eq. 14:
// −A0 σ̄_aa over the whole deformable material, mpm::AverageStressForce); and, only when the
// scene has a free rigid body (the flyer; docs/post.md reads these names), load_flyer
// (Σ over free rigid bodies of reaction · a: the contact force on the flyer, compression
// positive), and of the first free body flyer_velocity and flyer_displacement (along a),
// flyer_kinetic_energy and flyer_potential_energy (−M g·(X − X0)). Driven rigid plates
// count as driven bodies in displacement and load_driven.
std::vector<SeriesColumn> solver_series_columns(bool with_flyer = false);
// Whether the simulation has a free rigid body (the flyer columns are written).
bool has_flyer(const mpm::Simulation& sim);

// The series row as observers of the state after a step, column group by column group: the
// step's time and energies (StepDiagnostics), the boundaries' travel and loads (one pass over
// Simulation::boundary_reports()), the record layer (mpm::RecordLayerForce).
class SolverSeries {
 public:
  // specimen_area: A0 of load_average (mpm::AverageStressForce::initial_cross_section).
  SolverSeries(const mpm::Simulation& sim, const Eigen::Vector3d& axis, double specimen_area)
      : axis_(axis), record_(sim), average_(specimen_area, axis), with_flyer_(has_flyer(sim)) {}
  std::vector<SeriesColumn> columns() const { return solver_series_columns(with_flyer_); }
  std::vector<double> row(const mpm::Simulation& sim, const mpm::StepDiagnostics& d) const;

 private:
  Eigen::Vector3d axis_;
  mpm::RecordLayerForce record_;
  mpm::AverageStressForce average_;
  bool with_flyer_;
};

// The particles in their original point order (the solver re-sorts them), SI.
ParticleSnapshot solver_snapshot(const mpm::Simulation& sim);
// The same of `particles` at sim's step, whose ids are first_id, first_id + 1, … (in any
// order): a process's block of the points (mpm/domain.hpp, particles_in_id_block).
ParticleSnapshot solver_snapshot(const mpm::Simulation& sim, const mpm::Particles& particles, size_t first_id = 0);

}  // namespace latmpm
