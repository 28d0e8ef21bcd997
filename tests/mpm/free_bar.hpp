// The first free–free axial mode of a bar along x from 0 to L, shared by the shape-function
// tests: v(x, t) = v0 cos(πx/L) cos(ωt), ω = πc/L, period 2L/c. The momentum of the left half
// is ∝ cos(ωt): its zero crossings are half a period apart.
#pragma once
#include <cmath>
#include <vector>

#include "mpm/simulation.hpp"

namespace latmpm::mpm::test {

struct BarRun {
  Real period = 0;        // s, measured
  Real energy_ratio = 0;  // (kinetic + strain) / initial kinetic at the end
};

// Sets the mode's velocities on sim's points and runs it for `duration` (s).
inline BarRun run_first_axial_mode(Simulation& sim, Real length, Real v0, Real duration) {
  Real initial = 0;  // ½ Σ m v²: ½ ∫ ρ A v² dx for points at the cells' mid-points
  for (size_t p = 0; p < sim.particles().size(); ++p) {
    const Real v = v0 * std::cos(M_PI * sim.particles().position[p][0] / length);
    sim.mutable_particles().velocity[p] = ParticleVec3(v, 0, 0);
    initial += 0.5 * sim.particles().mass[p] * v * v;
  }
  std::vector<Real> crossings;
  Real previous_t = 0, previous_m = 1;
  sim.add_observer([&](const Simulation& sm, const StepDiagnostics& d) {
    const Particles& ps = sm.particles();
    Real m = 0;
    for (size_t p = 0; p < ps.size(); ++p)
      if (ps.position[p][0] < length / 2) m += ps.mass[p] * ps.velocity[p][0];
    if ((m > 0) != (previous_m > 0))
      crossings.push_back(previous_t + (d.time - previous_t) * previous_m / (previous_m - m));
    previous_t = d.time, previous_m = m;
  });
  sim.run_until(duration);
  BarRun out;
  if (crossings.size() >= 2) out.period = 2 * (crossings[1] - crossings[0]);
  const auto& d = sim.last_diagnostics();
  out.energy_ratio = (d.kinetic_energy + d.strain_energy) / initial;
  return out;
}

}  // namespace latmpm::mpm::test
