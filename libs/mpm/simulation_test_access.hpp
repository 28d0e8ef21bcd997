// Test-only access to the single stages of a Simulation's step, so the transfer tests can
// check each on its own (conservation, patch tests, DDMP's grid). Runs use
// Simulation::step(); nothing outside tests/ includes this header. The stages are compiled
// into the mpm library (simulation_test_access.cpp) rather than the tests, so they run with
// the library's floating-point flags and instantiate the stage templates only once.
#pragma once
#include <array>
#include <functional>
#include <vector>

#include "mpm/simulation.hpp"

namespace latmpm::mpm {

class SimulationTestAccess {
 public:
  struct GridTotals {
    Real mass = 0;                  // Σ m_i, kg
    Vec3 momentum = Vec3::Zero();   // Σ p_i (or Σ m_i v_i after a grid update), kg m/s
  };
  // Interpolated from the grid's new velocity, without changing any state:
  // v_p = Σ S_ip v_i (m/s) and L_p = Σ v_i ⊗ ∇S_ip (1/s).
  struct Gathered {
    std::vector<Vec3> velocity;
    std::vector<Mat3> velocity_gradient;
  };
  // A node of the active grid with its 8 lanes (sparse_grid.hpp).
  struct GridNode {
    std::array<int, 3> index;
    std::array<Real, 8> lanes;
  };

  // Resets the grid and maps mass and momentum (and internal force) of the particles to it.
  static void particles_to_grid(Simulation& sim);
  // Grid velocities from momentum (and force × dt), with boundary conditions.
  static void grid_update(Simulation& sim, Real dt);
  // Sets every grid node's new velocity to field(x_i) and its old velocity to zero.
  static void set_grid_velocity(Simulation& sim, const std::function<Vec3(const Vec3&)>& field);
  // Grid to particles: velocity, position, F and stress, with the current settings.
  static void grid_to_particles(Simulation& sim, Real dt);
  static GridTotals grid_totals(const Simulation& sim);
  static Gathered gather_from_grid(const Simulation& sim);
  // Every node of the active grid, block by block.
  static std::vector<GridNode> grid_nodes(const Simulation& sim);
  // Makes the next step's DDMP find start from scratch (find_ddmp_small_mass_nodes keeps the
  // last find's decisions where the masks around them did not change).
  static void forget_last_ddmp_find(Simulation& sim);
};

}  // namespace latmpm::mpm
