// Scheduled rigid bodies (motion_schedule.hpp, RigidMotion::scheduled): the schedule's
// velocity and displacement against hand-integrated values; a body in the solver that follows
// its schedule exactly, across a checkpoint; and a load–unload test of a block between penalty
// planes: an elastic block returns to zero force and its own height, a perfectly plastic one
// keeps the residual strain of elastic unloading from the yield stress, ε_peak + y0/E.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>

#include "core/errors.hpp"
#include "core/hdf5_file.hpp"
#include "mpm/j2_plasticity.hpp"
#include "mpm/simulation.hpp"
#include "point_builders.hpp"
#include "scratch_dir.hpp"

using namespace latmpm;
using namespace latmpm::mpm;
using namespace latmpm::mpm::test;

namespace {
constexpr Real h = 1e-3, side = 4e-3, E = 1e6, nu = 0.3, rho = 1000;

MotionSchedule schedule_of(std::initializer_list<std::pair<Real, Real>> time_and_vz) {
  MotionSchedule s;
  for (const auto& [t, vz] : time_and_vz) s.knots.push_back({t, Vec3(0, 0, vz)});
  return s;
}

RigidBodySettings plane(const std::string& name, Real z, const Vec3& normal) {
  RigidBodySettings p;
  p.name = name;
  p.motion = RigidMotion::fixed;
  p.shape = RigidShape::half_space;
  p.plane_point = Vec3(0, 0, z);
  p.plane_normal = normal;
  p.coupling = RigidCoupling::penalty;
  p.friction = 0;
  return p;
}

// The 4 mm block on a fixed floor (z = 0) under a platen on its top face that follows `schedule`.
std::unique_ptr<Simulation> block_under(const MotionSchedule& schedule, const MaterialParameters& material) {
  PointSet points = empty_point_set(h, 2);
  add_points(points, Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(side, side, side), "block");
  Settings s;
  s.cell_size = h;
  s.gravity = Vec3::Zero();
  s.threads = 2;
  auto sim = std::make_unique<Simulation>(points, std::vector<BodySettings>{deformable("block", material)}, s);
  sim->add_rigid_body(plane("floor", 0, Vec3::UnitZ()));
  RigidBodySettings platen = plane("platen", side, -Vec3::UnitZ());
  platen.motion = RigidMotion::scheduled;
  platen.schedule = schedule;
  platen.velocity = schedule.velocity(0);
  sim->add_rigid_body(platen);
  return sim;
}

// The block's height: the span of its points' centres along z (plus one point spacing, a constant).
Real height(const Simulation& sim) {
  Real lo = std::numeric_limits<Real>::infinity(), hi = -lo;
  for (const Vec3& x : sim.particles().position) lo = std::min(lo, x[2]), hi = std::max(hi, x[2]);
  return hi - lo + h / 2;
}
}  // namespace

TEST_CASE("A motion schedule is piecewise linear in velocity and integrates it exactly", "[mpm][schedule]") {
  // 0 → −2 m/s over 1 ms, held to 3 ms, → +1 m/s at 4 ms, held after. By hand: D(0.5 ms) =
  // −0.25 mm, D(1) = −1, D(3) = −5, D(3.5) = −5 − ½·0.5·(2 + 0.5) = −5.625, D(4) = −5.5,
  // D(5) = −4.5 mm.
  const MotionSchedule s = schedule_of({{0, 0}, {1e-3, -2}, {3e-3, -2}, {4e-3, 1}});
  const std::vector<std::array<Real, 3>> expected = {  // t (ms), V_z (m/s), D_z (mm)
      {0, 0, 0}, {0.5, -1, -0.25}, {1, -2, -1}, {2, -2, -3}, {3, -2, -5}, {3.5, -0.5, -5.625}, {4, 1, -5.5}, {5, 1, -4.5}};
  for (const auto& [t, v, d] : expected) {
    INFO("t = " << t << " ms");
    CHECK(s.velocity(t * 1e-3)[2] == Approx(v).margin(1e-12));
    CHECK(s.displacement(t * 1e-3)[2] == Approx(d * 1e-3).margin(1e-15));
    CHECK(s.displacement(t * 1e-3).head<2>().norm() == 0);
  }
  CHECK(s.max_speed() == 2);
  CHECK(s.first_direction() == Vec3(0, 0, -1));
  // Malformed schedules are refused, naming the knot.
  CHECK_THROWS_WITH(validate(schedule_of({}), "scene.toml:3", "rigid_bodies.p.schedule"),
                    Catch::Contains("rigid_bodies.p.schedule") && Catch::Contains("at least one knot"));
  CHECK_THROWS_WITH(validate(schedule_of({{1e-3, 0}}), "scene.toml:3", "rigid_bodies.p.schedule"),
                    Catch::Contains("schedule[0].time") && Catch::Contains("time 0"));
  CHECK_THROWS_WITH(validate(schedule_of({{0, 0}, {2e-3, 1}, {2e-3, 0}}), "scene.toml:3", "rigid_bodies.p.schedule"),
                    Catch::Contains("schedule[2].time") && Catch::Contains("increase strictly"));
  RigidBodySettings body = plane("p", 0, Vec3::UnitZ());
  body.motion = RigidMotion::scheduled;
  body.schedule = s;
  body.velocity = Vec3(0, 0, 1);
  CHECK_THROWS_AS(validate(body, "scene.toml:3"), InputError);  // its velocity is not V(0)
  body.motion = RigidMotion::fixed;
  body.velocity = Vec3::Zero();
  CHECK_THROWS_WITH(validate(body, "scene.toml:3"), Catch::Contains("only a scheduled body"));
}

TEST_CASE("A scheduled rigid body follows its schedule exactly, across a checkpoint", "[mpm][schedule]") {
  // The solver's steps (about 8 µs, set by the CFL condition) do not fall on the knots.
  const MotionSchedule s = schedule_of({{0, 0}, {0.13e-3, -0.05}, {0.41e-3, 0.02}, {0.6e-3, 0}});
  auto sim = block_under(s, elastic(E, nu, rho));
  Real worst = 0, worst_v = 0;
  size_t steps = 0;
  sim->add_observer([&](const Simulation&, const StepDiagnostics& d) {
    worst = std::max(worst, (d.rigid[1].displacement - s.displacement(d.time)).norm());
    worst_v = std::max(worst_v, (d.rigid[1].velocity - s.velocity(d.time)).norm());
    steps += 1;
  });
  sim->run_until(0.3e-3);
  const latmpm::test::ScratchDir scratch("motion-schedule");
  const std::filesystem::path path = scratch / "state.h5";
  {
    Hdf5File file(path.string(), Hdf5File::Mode::create);
    sim->save_state(file, "/state");
  }
  auto resumed = block_under(s, elastic(E, nu, rho));
  {
    Hdf5File file(path.string(), Hdf5File::Mode::read);
    resumed->load_state(file, "/state");
  }
  resumed->add_observer([&](const Simulation&, const StepDiagnostics& d) {
    worst = std::max(worst, (d.rigid[1].displacement - s.displacement(d.time)).norm());
  });
  sim->run_until(0.8e-3);
  resumed->run_until(0.8e-3);
  INFO(steps << " steps; worst displacement error " << worst << " m, velocity " << worst_v << " m/s");
  REQUIRE(steps > 50);
  CHECK(worst <= 1e-18);  // round-off of D(t) alone (|D| ~ 1e-5 m)
  CHECK(worst_v <= 1e-15);
  CHECK(resumed->rigid_states()[1].displacement == sim->rigid_states()[1].displacement);
  CHECK(resumed->rigid_states()[1].displacement[2] == Approx(s.displacement(0.8e-3)[2]).epsilon(1e-12));
}

TEST_CASE("Under load and unload an elastic block recovers its height and a plastic one keeps eps_peak + y0/E",
          "[mpm][schedule]") {
  // The platen ramps to 0.05 m/s down (0.5 ms), travels 0.31 mm down (the block takes ~4 % of
  // its 4 mm, the penalty springs the rest), reverses over 1 ms, rises 0.11 mm past its start
  // and stops: the block is free again.
  // 0.05 m/s is 0.14 % of the elastic wave speed (37 m/s): quasi-static; the heights are
  // averaged over the last 1.75 ms (the block rings at ~2 kHz after release).
  // References: elastic, the original height (no dissipation, nothing to keep); perfectly
  // plastic J2 (y0 = 1 % of E, no hardening, frictionless planes: uniaxial stress), elastic
  // unloading from the yield stress: ln(H_end/H0) = ln(H_peak/H0) + y0/E.
  const Real v = 0.05;
  const MotionSchedule s =
      schedule_of({{0, 0}, {0.5e-3, -v}, {6.5e-3, -v}, {7.5e-3, v}, {15.75e-3, v}, {16.25e-3, 0}});
  REQUIRE(s.displacement(16.25e-3)[2] == Approx(0.1125e-3).epsilon(1e-9));
  const Real y0 = 0.01 * E;
  const bool plastic = GENERATE(false, true);
  const MaterialParameters material =
      plastic ? j2_material(J2Parameters{E, nu, y0, y0, 0, 0}, rho) : elastic(E, nu, rho, MaterialKind::neo_hookean);
  auto sim = block_under(s, material);
  const Real h0 = height(*sim);
  Real peak_force = 0, h_peak = h0, h_end = 0, end_force = 0;
  int end_samples = 0;
  sim->add_observer([&](const Simulation& sm, const StepDiagnostics& d) {
    const Real force = -d.rigid[1].reaction[2];  // the platen pushes down: compression positive
    if (force > peak_force) peak_force = force;
    if (d.time > 6e-3 && d.time < 7e-3) h_peak = std::min(h_peak, height(sm));
    if (d.time > 16.25e-3) h_end += height(sm), end_force = std::max(end_force, std::abs(force)), end_samples += 1;
  });
  sim->run_until(18e-3);
  h_end /= end_samples;
  const Real eps_peak = std::log(h_peak / h0), eps_end = std::log(h_end / h0);
  INFO((plastic ? "J2" : "elastic") << ": peak force " << peak_force << " N, strain at peak " << eps_peak
                                    << ", after unloading " << eps_end << ", force at the end " << end_force << " N");
  REQUIRE(peak_force > 0);
  REQUIRE(eps_peak < -0.03);  // the load reached ~5 %
  CHECK(end_force == 0);      // no point touches the platen any more
  if (!plastic) {
    CHECK(std::abs(eps_end) < 0.02 * std::abs(eps_peak));
  } else {
    CHECK(eps_end == Approx(eps_peak + y0 / E).margin(0.1 * y0 / E));
  }
}
