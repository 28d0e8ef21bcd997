// The FLIP update's projection loss (StepDiagnostics::transfer_dissipation, step_stages.cpp):
// the grid's velocity increments carry Σ_I ½ m_I |Δv_I|², the points receive Σ_p ½ m_p
// |Σ_I S_Ip Δv_I|² of it, and the balance loses twice the difference (docs/solver.md,
// "Energy"). References: Jensen's inequality (the loss is never negative for weights
// S_Ip ≥ 0 that sum to one), and energy conservation of an elastic block bouncing off a
// frictionless penalty floor with pure FLIP (no blend): once it has left the floor, work in
// (none) = kinetic + strain + the loss, up to the explicit step's bounded oscillation.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "mpm/simulation.hpp"
#include "point_builders.hpp"

using namespace latmpm;
using namespace latmpm::mpm;
using namespace latmpm::mpm::test;

namespace {
constexpr Real h = 1e-3, side = 4e-3, nu = 0.3;

RigidBodySettings frictionless_floor() {
  RigidBodySettings f;
  f.name = "floor";
  f.motion = RigidMotion::fixed;
  f.shape = RigidShape::half_space;
  f.plane_normal = Vec3::UnitZ();
  f.coupling = RigidCoupling::penalty;
  f.friction = 0;
  return f;
}
}  // namespace

namespace {
struct Bounce {
  StepDiagnostics end;
  Real initial = 0;             // the block's kinetic energy at the start, J
  Real smallest_increment = 0;  // the loss's smallest change over one step, J
};

// A 4 mm steel block (2 points per 1 mm cell, uGIMP, pure FLIP) thrown at 10 m/s onto the
// floor, for four wave round trips: it lands (about one round trip), rings and flies off.
// Nothing does work on it and nothing in it dissipates physically (elastic, frictionless,
// flip = 1: no blend).
Bounce bounce(UpdateScheme scheme, Real cfl) {
  const Real E = 210e9, rho = 7850, v = 10;
  PointSet points = empty_point_set(h, 2);
  add_points(points, Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(side, side, side), "block");
  Settings s;
  s.cell_size = h;
  s.flip_blend = 1;
  s.cfl = cfl;
  s.scheme = scheme;
  s.threads = 2;
  Simulation sim(points, {deformable("block", elastic(E, nu, rho))}, s);
  sim.add_rigid_body(frictionless_floor());
  for (auto& u : sim.mutable_particles().velocity) u = Vec3(0, 0, -v).cast<ParticleReal>();
  Bounce b;
  b.initial = 0.5 * rho * side * side * side * v * v;
  Real previous = 0;
  sim.add_observer([&](const Simulation&, const StepDiagnostics& d) {
    b.smallest_increment = std::min(b.smallest_increment, d.transfer_dissipation - previous);
    previous = d.transfer_dissipation;
  });
  const Real c = std::sqrt(elastic(E, nu, rho).p_wave_modulus() / rho);
  sim.run_until(8 * side / c);
  b.end = sim.last_diagnostics();
  return b;
}
}  // namespace

TEST_CASE("An elastic block bouncing off a frictionless penalty floor conserves energy once the transfer's loss is booked",
          "[mpm][contact][energy]") {
  // USL: at the end, the springs empty, kinetic + strain + transfer_dissipation must be the
  // initial kinetic energy. Two steps: the loss is not a matter of the step size (it shrinks
  // slowly with it; docs/solver.md, "Energy").
  const Real cfl = GENERATE(0.3, 0.15);
  const Bounce b = bounce(UpdateScheme::usl, cfl);
  const StepDiagnostics& d = b.end;
  const Real unbooked = d.energy_error - d.transfer_dissipation;
  INFO("cfl " << cfl << ": initial kinetic " << b.initial << " J; at the end kinetic " << d.kinetic_energy
              << ", strain " << d.strain_energy << ", springs " << d.contact_energy << ", transfer loss "
              << d.transfer_dissipation << " J; energy_error " << d.energy_error << " J (" << unbooked
              << " J without the loss); smallest step of the loss " << b.smallest_increment << " J");
  CHECK(d.contact_energy == 0);                           // it has left the floor
  CHECK(b.smallest_increment >= -1e-12 * b.initial);      // Jensen: never negative
  CHECK(d.transfer_dissipation > 0.1 * b.initial);        // the landing loses much to the projection
  CHECK(std::abs(d.energy_error) < 0.02 * b.initial);     // booked, the balance closes
  CHECK(std::abs(d.energy_error) < 0.1 * std::abs(unbooked));
}

TEST_CASE("MUSL and USF book no projection loss: their work is not taken at the new nodal velocities",
          "[mpm][contact][energy]") {
  // MUSL takes the strain rate from the remapped velocity and USF from the old one, so the
  // step's work is Σ_p m_p v_p^{n+1}·Δv_p or Σ_I p_I·Δv_I and the projection term of USL's
  // balance does not arise (step_stages.cpp, absorb_tallies): nothing is booked.
  const UpdateScheme scheme = GENERATE(UpdateScheme::musl, UpdateScheme::usf);
  const Bounce b = bounce(scheme, 0.3);
  INFO(to_string(scheme) << ": energy_error " << b.end.energy_error << " J of " << b.initial << " J");
  CHECK(b.end.transfer_dissipation == 0);
  CHECK(b.end.contact_energy == 0);
  // Their balance closes without it (measured +1.2 % MUSL, +2.4 % USF; USL's unbooked loss
  // is −23 %): booking USL's term here would push it up by that much.
  CHECK(std::abs(b.end.energy_error) < 0.05 * b.initial);
}
