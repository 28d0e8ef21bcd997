// Paper B's SHPB specimen at QUICK size (docs/paper-b.md): the B2 hexahedral cylinder
// (d0 = l0 = 4 mm, 384 CPDI1 domains), J2 42CrMo4, between two penalty planes with Coulomb
// friction μ = 0.1, the incident one driven at 10.6476 m/s, on the 0.4 mm grid G4, paper B's
// Δt = 5 ns (as cfl), 10 µs. References: the energy balance — the driven plane's work
// ∫ f_i V dt against kinetic + elastic (Eq. 12) + plastic work (Σ V0 Σ Δα y) — and the
// balance of the two planes' forces; no point passes either plane.
#include <catch2/catch.hpp>

#include <cmath>

#include "hexmesh/hex_mesh.hpp"
#include "hexmesh/hex_points.hpp"
#include "mpm/j2_plasticity.hpp"
#include "mpm/simulation.hpp"
#include "point_builders.hpp"

using namespace latmpm;
using namespace latmpm::mpm;
using namespace latmpm::mpm::test;

namespace {
constexpr Real diameter = 4e-3, length = 4e-3, speed = 10.6476, h = 0.4e-3, mu = 0.1;

RigidBodySettings plane(const std::string& name, Real z, Real normal_z, Real velocity_z) {
  RigidBodySettings p;
  p.name = name;
  p.shape = RigidShape::half_space;
  p.plane_point = Vec3(0, 0, z);
  p.plane_normal = Vec3(0, 0, normal_z);
  p.motion = velocity_z == 0 ? RigidMotion::fixed : RigidMotion::driven;
  p.velocity = Vec3(0, 0, velocity_z);
  p.coupling = RigidCoupling::penalty;
  p.friction = mu;
  return p;
}
}  // namespace

TEST_CASE("The QUICK SHPB specimen in CPDI1 and J2 closes its energy balance with the plastic work", "[mpm][cpdi][shpb]") {
  const PointSet points = hex_mesh_points(cylinder_hex_mesh(paper_b_cylinder(2, diameter, length)), "specimen", h);
  REQUIRE(points.size() == 384);
  const MaterialParameters m = j2_material(steel_42crmo4_400c(), 7850);
  Settings s;
  s.cell_size = h;
  s.shape_function = ShapeFunctionKind::cpdi1;
  s.cfl = 0.0714;  // Δt ≈ 5 ns: h / c = 0.4 mm / 5708 m/s = 70 ns
  s.flip_blend = 0.99;
  s.threads = 2;
  Simulation sim(points, {deformable("specimen", m)}, s);
  sim.add_rigid_body(plane("incident", length, -1, -speed));
  sim.add_rigid_body(plane("transmitter", 0, 1, 0));
  Real z_min = 1, z_max = -1, plane_work = 0, f_i_late = 0, f_t_late = 0;
  sim.add_observer([&](const Simulation& sm, const StepDiagnostics& d) {
    const Real f_i = -d.rigid[0].reaction[2], f_t = d.rigid[1].reaction[2];
    plane_work += f_i * speed * d.dt;
    if (d.time > 8e-6) f_i_late += f_i * d.dt, f_t_late += f_t * d.dt;  // means over the last 2 µs
    const Real top = length - speed * d.time;
    for (const Vec3& x : sm.particles().position) z_min = std::min(z_min, x[2]), z_max = std::max(z_max, x[2] - top);
  });
  sim.run_until(10e-6);
  const StepDiagnostics& d = sim.last_diagnostics();
  const Real stored = d.kinetic_energy + d.strain_energy + d.plastic_dissipation;
  INFO("plane work " << plane_work << " J; kinetic " << d.kinetic_energy << " J, elastic " << d.strain_energy
                     << " J, plastic " << d.plastic_dissipation << " J; mean f_i " << f_i_late / 2e-6 << " N, f_t "
                     << f_t_late / 2e-6 << " N");
  CHECK(d.plastic_dissipation > 0.8 * plane_work);  // a metal past yield: most work is plastic
  // Friction (μ = 0.1 at 2.7 % strain) and the contact springs' stretch are outside the sum.
  CHECK(std::abs(stored - plane_work) < 0.02 * plane_work);
  CHECK(std::abs(f_i_late - f_t_late) < 0.01 * f_i_late);  // the specimen is in equilibrium
  // Paper B handles contact at the material points: none passes a plane.
  CHECK(z_min > 0);
  CHECK(z_max < 0);
}
