// Observers of the state after each step (Simulation::add_observer): checks and
// measurements that are about an experiment, not about advancing the model. The series a run
// writes is a list of such observers too (libs/run_output/solve_run.cpp).
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

}  // namespace latmpm::mpm
