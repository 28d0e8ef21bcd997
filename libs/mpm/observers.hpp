// Observers of the state after each step (Simulation::add_observer): checks and
// measurements that are about an experiment, not about advancing the model. The series a run
// writes is a list of such observers too (libs/run_output/solver_series.hpp, solve_run.cpp).
#pragma once
#include <vector>

#include "mpm/simulation.hpp"

namespace latmpm::mpm {

// Stops a run (NumericalError) once a driven body has reached a fixed one: see observers.cpp.
// Built into every Simulation as its first observer.
class BodiesApartCheck {
 public:
  // The point bodies' boxes as the simulation holds them now (before its first step).
  explicit BodiesApartCheck(const Simulation& sim);
  void operator()(const Simulation& sim, const StepDiagnostics& d) const;

 private:
  std::vector<Vec3> lo_, hi_, pad_;  // per point body: its points' box at the start, and their
                                     // largest domain half-size, m
};

// The record layer's force A · σ̄_zz (N, tension positive; Paper A Sec. 5.1): σ̄_zz the
// current-volume average Σ σ_zz J V0 / Σ J V0 over the deformable points carrying
// Settings::record_tag, A = Simulation::record_area(); 0 without record points. Read from the
// state after a step (the gather kernel no longer sums it). The sums run bucket by bucket in
// the gather's lane order (eight particles a pack, lanes added at the bucket's end), so the
// value is the one the kernel's own sum gave, bit for bit.
class RecordLayerForce {
 public:
  explicit RecordLayerForce(const Simulation& sim) : area_(sim.record_area()) {}
  Real operator()(const Simulation& sim) const;

 private:
  Real area_;  // m²
};

}  // namespace latmpm::mpm
