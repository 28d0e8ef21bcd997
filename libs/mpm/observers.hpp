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

// Paper B's averaged force f_a (Eq. 14): A0 times the current-volume average of the stress
// along the loading axis a over every deformable point, f_a = A0 Σ σ_aa v_p / Σ v_p with
// v_p = J_p V0_p, in N, tension positive (the series negates it). A0 = ΣV0 / l0, l0 the
// deformable points' extent along a (their domains' half-sizes included) in the state the
// simulation starts from (initial_cross_section): the initial cross-section of a prismatic
// specimen as discretised (paper B: π d0²/4 of the cylinder; the mesh's own area keeps f_a
// consistent with its volume, docs/paper-b.md). Unlike the contact forces, f_a averages the
// whole specimen: it smooths the waves and leaves out the contact layer (paper B Sec. 4).
class AverageStressForce {
 public:
  AverageStressForce(Real area, const Vec3& axis) : axis_(axis.normalized()), area_(area) {}
  // A0 (m²) of the simulation's deformable points as they are now: call it before the first
  // step (a resumed run takes it before loading its checkpoint).
  static Real initial_cross_section(const Simulation& sim, const Vec3& axis);
  Real operator()(const Simulation& sim) const;
  Real area() const { return area_; }

 private:
  Vec3 axis_;  // unit
  Real area_;  // m², A0
};

}  // namespace latmpm::mpm
