// The explicit MPM solver: particles on a sparse background grid, advanced one step at a
// time. The step reads like Taichi's mpm99 — reset grid, particles to grid, grid update
// with boundary conditions, grid to particles — with the shape function, material model,
// update scheme and boundary conditions as named parts (docs/solver.md has the equations).
//
//   Simulation sim(points, bodies, settings);          // InputError on inconsistent input
//   sim.add_observer([&](const Simulation& s, const StepDiagnostics& d) { ... });
//   sim.run_until(0.015);                               // NumericalError if it goes unstable
//
// Every step throws NumericalError (naming step, particle and position) on NaN/Inf,
// J ≤ Settings::min_jacobian (inverted or crushed),
// a particle leaving the grid's coordinate range, a fixed time step above the stable limit,
// or runaway kinetic energy. The state stays readable after the throw, so a caller can save
// what it has.
#pragma once
#include <array>
#include <functional>
#include <memory>
#include <vector>

#include "mpm/body.hpp"
#include "mpm/boundary.hpp"
#include "mpm/diagnostics.hpp"
#include "mpm/domain.hpp"
#include "mpm/particles.hpp"
#include "mpm/rigid_body.hpp"
#include "mpm/settings.hpp"
#include "mpm/solver_state.hpp"

namespace latmpm {
struct PointSet;
class Hdf5File;
}

namespace latmpm::mpm {

struct StepContext;

class Simulation {
 public:
  using Observer = std::function<void(const Simulation&, const StepDiagnostics&)>;

  // One BodySettings per body name of the point set (matched by name, order free). Throws
  // InputError(where, field, problem) naming the body or setting that does not fit.
  Simulation(const PointSet& points, const std::vector<BodySettings>& bodies,
             const Settings& settings, const std::string& where = "scene");
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  // Advances one time step and returns its diagnostics (observers are called too).
  const StepDiagnostics& step();
  // Steps until time ≥ end_time (s); the last step is shortened to land on end_time.
  void run_until(Real end_time);
  // Called after every step with the state at the end of that step.
  void add_observer(Observer observer);
  // A geometric rigid body (rigid_body.hpp: a driven plate or a free flyer); before the
  // first step. Throws InputError for invalid settings, a duplicate name or a started run.
  void add_rigid_body(const RigidBodySettings& body);
  const std::vector<RigidBodySettings>& rigid_bodies() const { return rigid_bodies_; }
  // The rigid bodies' states now (their boundaries', in rigid_bodies() order).
  const std::vector<RigidBodyState>& rigid_states() const { return state_.diagnostics.rigid; }
  // Every boundary of the model (boundary.hpp): point-defined ones in body order, then the
  // geometric rigid bodies in the order they were added.
  const std::vector<Boundary>& boundaries() const { return state_.boundaries; }
  // What the series shows of each boundary, in boundaries() order.
  std::vector<BoundaryReport> boundary_reports() const;
  // Per point, in particles() order: the penalty contact force of the last step (N,
  // rigid_contact.hpp; zero for points not in contact). Empty without penalty bodies.
  const std::vector<Vec3>& contact_forces() const;

  // The time step the next step() will take (s): the automatic stable step, or the fixed
  // one. Throws NumericalError if a fixed step exceeds the stable limit.
  Real next_time_step() const;
  Real stable_time_step() const;  // cfl · h / max_p(c_p + |v_p|), s

  const Particles& particles() const { return state_.particles; }
  const std::vector<BodySettings>& bodies() const { return bodies_; }
  const Settings& settings() const { return settings_; }
  const StepDiagnostics& last_diagnostics() const { return state_.diagnostics; }
  Real time() const { return state_.diagnostics.time; }
  int64_t step_count() const { return state_.diagnostics.step; }
  // Blocks of grid nodes allocated now (each 4×4×4 nodes), and their memory in bytes.
  size_t active_grid_blocks() const;
  size_t grid_memory_bytes() const;
  size_t particle_memory_bytes() const;

  // Record-layer area A (m²) of the RecordLayerForce observer (observers.hpp); 0 without
  // record points.
  Real record_area() const { return record_area_; }

  // Checkpoints (simulation_state.cpp): everything a continued run needs to give the same
  // results bit for bit — particles in their internal order with their buckets, time, step,
  // diagnostics and accumulated work, rigid-body state, the carried stable-step inputs —
  // into / from the HDF5 group `group` of an open file. load_state needs a Simulation built
  // from the same scene (same bodies, settings, rigid bodies); throws InputError otherwise.
  // On several processes (domain.hpp) all three are collective: rank 0's save_state lays
  // the state out at its one-process size (file: nullptr on the others) and, after rank 0
  // closed the file, save_state_rows (rank 0's path) has every process write its
  // particles and bucket rows into it at once (parallel HDF5), so the file is the one a
  // single process writes; load_state reads the whole file on every process, which keeps
  // its share: a checkpoint of N processes resumes on any number. One process: save_state
  // writes everything and save_state_rows does nothing.
  void save_state(Hdf5File& file, const std::string& group) const;
  void save_state(Hdf5File* file, const std::string& group) const;
  void save_state_rows(const std::string& path, const std::string& group) const;
  void load_state(const Hdf5File& file, const std::string& group);

  // Set-up of the initial state (initial velocities, prestress); call before the first
  // step. Velocities, positions and stresses set here are taken as the initial state.
  Particles& mutable_particles();

  // The state the step works on (solver_state.hpp): particles, grid, boundaries, time.
  // With several processes (domain.hpp), particles() and state() are this process's part.
  const SolverState& state() const { return state_; }
  const Domain& domain() const;

 private:
  // Single stages of a step for the transfer tests (simulation_test_access.hpp).
  friend class SimulationTestAccess;
  void advance(Real dt);
  void check_body_speed(Real speed, const std::string& where, const std::string& field) const;
  void finish_step(Real dt, Real stable_dt);
  void refresh_rigid_states();  // state_.diagnostics.rigid from the boundaries
  // The run's configuration, rebuilt from the scene (never saved).
  std::vector<BodySettings> bodies_;
  Settings settings_;
  std::vector<RigidBodySettings> rigid_bodies_;  // as added (their state: in state_.boundaries)
  std::vector<Observer> observers_;
  Real record_area_ = 0;
  // What a continued run needs (save_state), and the stepping machinery.
  SolverState state_;
  std::unique_ptr<StepContext> context_;
};

}  // namespace latmpm::mpm
