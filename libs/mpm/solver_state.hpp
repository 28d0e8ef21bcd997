// The state of a run, kept apart from the stepping (issue 13 point 4): the particles with
// their sort into buckets, the background grid, the boundaries, the time and the energy
// ledger. The stages of a step (step_stages.hpp) are functions over this state and a
// StepContext (settings, body table, threads, domain, per-step scratch); observers see it
// through Simulation after each step; save_state / load_state (simulation_state.cpp) write
// and read everything here except the grid, which every step rebuilds from the particles.
#pragma once
#include <vector>

#include "mpm/boundary.hpp"
#include "mpm/diagnostics.hpp"
#include "mpm/particle_buckets.hpp"
#include "mpm/particles.hpp"
#include "mpm/sparse_grid.hpp"

namespace latmpm::mpm {

// What the stable time step and the energy balance carry from one step to the next.
struct CarriedState {
  Real max_speed = 0;              // m/s, deformable and driven points, rigid bodies
  Real max_wave_speed = 0;         // m/s
  Real initial_energy = 0;         // J, kinetic + strain energy of the deformable points at the start
  std::vector<Vec3> initial_centre;  // per body, m
  Real initial_rigid_energy = 0;   // J, Σ kinetic + potential of free rigid bodies at the start
  Real driven_rigid_work = 0;      // J, work of driven and fixed rigid bodies on the model so far
};

struct SolverState {
  Particles particles;      // structure of arrays (particle_fields.hpp), in bucket order
  ParticleBuckets buckets;  // the particles' sort by (bucket, body, cell)
  bool needs_sort = true;   // positions moved past the buckets' drift, or were set from outside
  SparseGrid grid;          // lanes of the active blocks (sparse_grid.hpp); rebuilt every step
  bool grid_holds_velocity = false;  // lanes 1–3: momentum (false) or velocity (true)
  std::vector<Boundary> boundaries;  // point-defined in body order, then geometric rigid bodies
  StepDiagnostics diagnostics;       // time, step count and energies after the last step
  CarriedState carried;
};

}  // namespace latmpm::mpm
