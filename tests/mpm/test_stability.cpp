// Runs that go wrong stop with NumericalError naming step, particle and position; input
// that cannot work stops with InputError naming the field.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>

#include "core/errors.hpp"
#include "mpm/simulation.hpp"
#include "point_builders.hpp"

using namespace latmpm;
using namespace latmpm::mpm;
using namespace latmpm::mpm::test;

namespace {
PointSet cube(Real h) {
  PointSet ps = empty_point_set(h, 2);
  add_points(ps, Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(4 * h), "cube");
  return ps;
}

Settings base_settings(Real h) {
  Settings s;
  s.cell_size = h;
  s.threads = 1;
  return s;
}

const MaterialParameters rubber = elastic(1e6, 0.3, 1000);

// The message of the exception of type E that f throws, or "(nothing thrown)".
template <class E, class F>
std::string message_of(F&& f) {
  try {
    f();
  } catch (const E& e) {
    return e.what();
  }
  return "(nothing thrown)";
}
}  // namespace

TEST_CASE("A time step above the stable limit is refused", "[mpm][stability]") {
  const Real h = 1e-3;
  Settings s = base_settings(h);
  const Real c = std::sqrt(rubber.p_wave_modulus() / rubber.density);
  s.fixed_time_step = 1.5 * h / c;
  Simulation sim(cube(h), {deformable("cube", rubber)}, s);
  CHECK_THAT(message_of<NumericalError>([&] { sim.step(); }), Catch::Matchers::Contains("exceeds the stable limit"));
  s.fixed_time_step = 0.5 * h / c;
  Simulation ok(cube(h), {deformable("cube", rubber)}, s);
  CHECK_NOTHROW(ok.step());
}

TEST_CASE("A collapsing body stops the run with the step, particle and position", "[mpm][stability]") {
  // Kinetic energy far beyond what the linear elastic cube can store: it is crushed until a
  // particle inverts. The run must stop there, before NaN reaches any output.
  const Real h = 1e-3;
  Simulation sim(cube(h), {deformable("cube", rubber)}, base_settings(h));
  const Vec3 centre = Vec3::Constant(2 * h);
  for (size_t p = 0; p < sim.particles().size(); ++p)
    sim.mutable_particles().velocity[p] = (-1e5 * (sim.particles().position[p] - centre)).cast<ParticleReal>();  // 1/s
  std::string msg;
  try {
    for (int n = 0; n < 5000; ++n) sim.step();
  } catch (const NumericalError& e) {
    msg = e.what();
  }
  INFO(msg);
  CHECK_THAT(msg, Catch::Matchers::StartsWith("step ") && Catch::Matchers::Contains("particle ") &&
                      Catch::Matchers::Contains(") m "));
  for (const auto& x : sim.particles().position) CHECK(x.allFinite());
}

TEST_CASE("An inverted particle stops the run", "[mpm][stability]") {
  const Real h = 1e-3;
  Simulation sim(cube(h), {deformable("cube", rubber)}, base_settings(h));
  // A particle whose F is nearly singular: the first step's update inverts it.
  sim.mutable_particles().deformation[5] = ParticleMat3::Identity() * ParticleReal(1e-3);
  sim.mutable_particles().deformation[5](0, 0) = -1e-3;
  CHECK_THAT(message_of<NumericalError>([&] { sim.step(); }), Catch::Matchers::Contains("J = ") && Catch::Matchers::Contains("particle 5"));
}

namespace {
// A plate driven at 1 m/s into a rubber cube (h = 1 mm), 30 steps with the settings `change`
// makes to base_settings; the last step's diagnostics.
StepDiagnostics drive_plate_into_cube(const std::function<void(Settings&)>& change) {
  const Real h = 1e-3;
  PointSet points = cube(h);
  add_points(points, Eigen::Vector3d(0, 0, 4 * h), Eigen::Vector3d(4 * h, 4 * h, 5 * h), "plate");
  Settings s = base_settings(h);
  change(s);
  Simulation sim(points, {deformable("cube", rubber), rigid("plate", BodyRole::driven, Vec3(0, 0, -1), 1000)}, s);
  for (int n = 0; n < 30; ++n) sim.step();
  return sim.last_diagnostics();
}
}  // namespace

TEST_CASE("Kinetic energy beyond the energy put in stops the run", "[mpm][stability]") {
  // A plate drives into a cube: kinetic energy comes only from the plate's work. With the
  // default budget (10 × the work) the run goes on; with a budget below the kinetic share
  // of the work the check fires, which shows it compares the right quantities.
  const auto d = drive_plate_into_cube([](Settings&) {});
  CHECK(d.kinetic_energy > 0);
  CHECK(d.kinetic_energy + d.strain_energy <= 1.01 * d.external_work);
  const std::string msg =
      message_of<NumericalError>([&] { drive_plate_into_cube([](Settings& s) { s.runaway_energy_factor = 0.01; }); });
  CHECK_THAT(msg, Catch::Matchers::Contains("runaway kinetic energy") && Catch::Matchers::Contains("the fastest particle: "));
}

TEST_CASE("An energy balance off by more than the energy put in stops the run", "[mpm][stability]") {
  // The same plate and cube: with the default bound (10 × the energy put in) the run goes on;
  // with a bound of 1e-3 × the energy put in, below the balance's own small error, the check
  // fires, naming the balance and the fastest deformable particle, while the kinetic energy
  // stays within its own bound (10 ×): it compares the balance, not the kinetic energy.
  const auto d = drive_plate_into_cube([](Settings&) {});
  // Something to compare: the driven plate's work and motion leave the balance a small error.
  REQUIRE(std::abs(d.energy_error) > 1e-9);
  const std::string msg =
      message_of<NumericalError>([&] { drive_plate_into_cube([](Settings& s) { s.energy_error_factor = 1e-3; }); });
  INFO(msg);
  CHECK_THAT(msg, Catch::Matchers::StartsWith("step ") && Catch::Matchers::Contains("the energy balance is off by") &&
                      Catch::Matchers::Contains("the fastest particle: ") && Catch::Matchers::Contains("of body 'cube'") &&
                      Catch::Matchers::Contains(") m, "));
}

TEST_CASE("Inconsistent scenes are refused with the field that is wrong", "[mpm][stability]") {
  const Real h = 1e-3;
  const PointSet points = cube(h);
  CHECK_THAT(message_of<InputError>([&] { Simulation(points, {}, base_settings(h)); }), Catch::Matchers::Contains("no settings for body 'cube'"));
  CHECK_THAT(message_of<InputError>([&] { Simulation(points, {deformable("cube", rubber), deformable("plate", rubber)}, base_settings(h)); }), Catch::Matchers::Contains("bodies.plate"));
  CHECK_THAT(message_of<InputError>([&] { Simulation(points, {deformable("cube", elastic(1e6, 0.5, 1000))}, base_settings(h)); }), Catch::Matchers::Contains("poisson_ratio"));
  Settings bad = base_settings(h);
  bad.cfl = 1.5;
  CHECK_THAT(message_of<InputError>([&] { Simulation(points, {deformable("cube", rubber)}, bad); }), Catch::Matchers::Contains("cfl"));
  bad = base_settings(h);
  bad.cell_size = 0;
  CHECK_THAT(message_of<InputError>([&] { Simulation(points, {deformable("cube", rubber)}, bad); }), Catch::Matchers::Contains("cell_size"));
}

TEST_CASE("A driven or rigid body faster than the material's wave speed is refused", "[mpm][stability]") {
  // c = sqrt((λ + 2μ)/ρ) = 36.7 m/s for the rubber cube: a plate at 40 m/s would shock it.
  const Real h = 1e-3;
  PointSet points = cube(h);
  add_points(points, Eigen::Vector3d(0, 0, 4 * h), Eigen::Vector3d(4 * h, 4 * h, 5 * h), "plate");
  const Real c = std::sqrt(rubber.p_wave_modulus() / rubber.density);
  auto build = [&](Real speed) {
    return std::make_unique<Simulation>(
        points, std::vector<BodySettings>{deformable("cube", rubber), rigid("plate", BodyRole::driven, Vec3(0, 0, -speed), 1000)},
        base_settings(h));
  };
  CHECK_NOTHROW(build(0.9 * c));
  CHECK_THAT(message_of<InputError>([&] { build(1.1 * c); }),
             Catch::Matchers::Contains("bodies.plate.velocity") && Catch::Matchers::Contains("wave speed"));
  auto sim = build(1);
  RigidBodySettings flyer;
  flyer.name = "flyer";
  flyer.box_min = Vec3(0, 0, 6 * h);
  flyer.box_max = Vec3(4 * h, 4 * h, 7 * h);
  flyer.motion = RigidMotion::free;
  flyer.mass = 1;
  flyer.velocity = Vec3(0, 0, -1.1 * c);
  CHECK_THAT(message_of<InputError>([&] { sim->add_rigid_body(flyer); }),
             Catch::Matchers::Contains("rigid_bodies.flyer.velocity"));
}

TEST_CASE("A driven plate that reaches the fixed base stops the run", "[mpm][stability]") {
  // A 3-cell-thin cube between a base and a plate at 5 m/s, with the J check off so the
  // squeezed material lets the plate through: the run stops when the plate's surface
  // reaches the base's, not before, naming both bodies. The base is a point body or a fixed
  // rigid body (a box of the same extent, or the half-space below z = 0); the plate a point
  // body or a driven rigid box.
  enum class Base { points, rigid_box, rigid_half_space };
  const Base kind = GENERATE(Base::points, Base::rigid_box, Base::rigid_half_space);
  const bool rigid_plate = GENERATE(false, true);
  const Real h = 1e-3;
  const Vec3 plate_velocity(0, 0, -5);
  PointSet points = empty_point_set(h, 2);
  add_points(points, Eigen::Vector3d::Zero(), Eigen::Vector3d(4 * h, 4 * h, 3 * h), "cube");
  if (kind == Base::points) add_points(points, Eigen::Vector3d(0, 0, -h), Eigen::Vector3d(4 * h, 4 * h, 0), "base");
  if (!rigid_plate) add_points(points, Eigen::Vector3d(0, 0, 3 * h), Eigen::Vector3d(4 * h, 4 * h, 4 * h), "plate");
  Settings s = base_settings(h);
  s.min_jacobian = 0;  // let the squeezed material through: the check under test must fire
  std::vector<BodySettings> bodies = {deformable("cube", rubber)};
  if (kind == Base::points) bodies.push_back(rigid("base", BodyRole::fixed, Vec3::Zero(), 1000));
  if (!rigid_plate) bodies.push_back(rigid("plate", BodyRole::driven, plate_velocity, 1000));
  Simulation sim(points, bodies, s);
  if (rigid_plate) {
    RigidBodySettings plate;
    plate.name = "plate";
    plate.box_min = Vec3(0, 0, 3 * h);
    plate.box_max = Vec3(4 * h, 4 * h, 4 * h);
    plate.velocity = plate_velocity;
    sim.add_rigid_body(plate);
  }
  if (kind != Base::points) {
    RigidBodySettings base;
    base.name = "base";
    base.motion = RigidMotion::fixed;
    base.shape = kind == Base::rigid_box ? RigidShape::box : RigidShape::half_space;
    base.box_min = Vec3(0, 0, -h);
    base.box_max = Vec3(4 * h, 4 * h, 0);
    base.plane_normal = Vec3::UnitZ();  // through the origin
    sim.add_rigid_body(base);
  }
  const std::string message = message_of<NumericalError>([&] { sim.run_until(4 * h / 5); });
  INFO("base " << int(kind) << (rigid_plate ? ", rigid plate: " : ", point plate: ") << message);
  CHECK_THAT(message, Catch::Matchers::Contains("'plate' has reached the fixed body 'base'"));
  CHECK(5 * sim.time() == Approx(3 * h).margin(0.05 * h));  // the gap was the cube's 3 mm
}
