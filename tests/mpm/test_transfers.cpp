// Particle–grid transfers: conservation through P2G and G2P, exact rigid translation, and
// uniform-strain patches reproduced to round-off, for every shape function and scheme.
#include <catch2/catch.hpp>

#include <random>

#include "mpm/simulation.hpp"
#include "mpm/simulation_test_access.hpp"
#include "point_builders.hpp"

using namespace latmpm;
using namespace latmpm::mpm;
using namespace latmpm::mpm::test;

namespace {
const auto all_shapes = {ShapeFunctionKind::linear, ShapeFunctionKind::ugimp, ShapeFunctionKind::cpgimp,
                         ShapeFunctionKind::bspline2, ShapeFunctionKind::bspline3, ShapeFunctionKind::ddmp};

Settings settings_for(ShapeFunctionKind shape, Real h) {
  Settings s;
  s.cell_size = h;
  s.shape_function = shape;
  s.threads = 2;
  return s;
}

// A 12×10×9-cell block of points, ppc 2, starting off the origin so it spans several
// buckets and negative coordinates.
PointSet block_points(Real h) {
  PointSet ps = empty_point_set(h, 2);
  add_points(ps, h * Eigen::Vector3d(-5, -3, 2), h * Eigen::Vector3d(7, 7, 11), "block");
  return ps;
}

std::vector<BodySettings> block_body() { return {deformable("block", elastic(1e6, 0.3, 1000))}; }
}  // namespace

TEST_CASE("Particles-to-grid and grid-to-particles conserve mass and momentum", "[mpm][transfer]") {
  const auto shape = GENERATE(values(all_shapes));
  const Real h = 1e-3;
  PointSet points = block_points(h);
  // Jitter the points inside their cells and vary their volumes: no symmetry to hide errors.
  std::mt19937 rng(5);
  std::uniform_real_distribution<Real> u(-0.2, 0.2);
  for (size_t p = 0; p < points.size(); ++p) {
    points.position[p] += h * Eigen::Vector3d(u(rng), u(rng), u(rng));
    points.volume[p] *= 1 + u(rng);
  }
  Simulation sim(points, block_body(), settings_for(shape, h));
  Real mass = 0;
  Vec3 momentum = Vec3::Zero();
  for (size_t p = 0; p < sim.particles().size(); ++p) {
    ParticleVec3& v = sim.mutable_particles().velocity[p];
    v = (Vec3(u(rng), u(rng), u(rng)) + Vec3(1, -2, 0.5)).cast<ParticleReal>();
    mass += sim.particles().mass[p];
    momentum += Real(sim.particles().mass[p]) * v.cast<Real>();
  }
  INFO("shape " << to_string(shape));
  SimulationTestAccess::particles_to_grid(sim);
  const auto grid = SimulationTestAccess::grid_totals(sim);
  CHECK(std::abs(grid.mass - mass) <= 1e-12 * mass);
  CHECK((grid.momentum - momentum).norm() <= 1e-12 * momentum.norm());

  // No stress and no gravity: the grid update keeps each node's velocity, and a PIC gather
  // hands the grid's momentum back to the particles.
  SimulationTestAccess::grid_update(sim, 1e-6);
  CHECK((SimulationTestAccess::grid_totals(sim).momentum - momentum).norm() <= 1e-12 * momentum.norm());
  Settings pic = sim.settings();
  pic.flip_blend = 0;
  Simulation pic_sim(points, block_body(), pic);
  for (size_t p = 0; p < pic_sim.particles().size(); ++p)
    pic_sim.mutable_particles().velocity[p] = sim.particles().velocity[p];
  SimulationTestAccess::particles_to_grid(pic_sim);
  SimulationTestAccess::grid_update(pic_sim, 1e-6);
  const Vec3 grid_momentum = SimulationTestAccess::grid_totals(pic_sim).momentum;
  SimulationTestAccess::grid_to_particles(pic_sim, 1e-6);
  Vec3 after = Vec3::Zero();
  for (size_t p = 0; p < pic_sim.particles().size(); ++p)
    after += Real(pic_sim.particles().mass[p]) * pic_sim.particles().velocity[p].cast<Real>();
  CHECK((after - grid_momentum).norm() <= 1e-12 * momentum.norm());
}

TEST_CASE("A rigid translation is exact for every shape function and update scheme", "[mpm][transfer]") {
  const auto shape = GENERATE(values(all_shapes));
  const auto scheme = GENERATE(UpdateScheme::usl, UpdateScheme::usf, UpdateScheme::musl);
  const Real h = 1e-3;
  const Vec3 velocity(3, -2, 4.5);  // m/s: fast enough to cross cell faces
  const PointSet points = block_points(h);
  Settings s = settings_for(shape, h);
  s.scheme = scheme;
  s.flip_blend = 0.9;
  Simulation sim(points, block_body(), s);
  for (auto& v : sim.mutable_particles().velocity) v = velocity.cast<ParticleReal>();
  for (int n = 0; n < 40; ++n) sim.step();
  INFO("shape " << to_string(shape) << ", scheme " << to_string(scheme));
  const Particles& ps = sim.particles();
  Real position_error = 0, velocity_error = 0, strain_error = 0, stress = 0;
  for (size_t p = 0; p < ps.size(); ++p) {
    position_error = std::max(position_error, (ps.position[p] - points.position[ps.id[p]] - sim.time() * velocity).norm());
    velocity_error = std::max(velocity_error, (ps.velocity[p].cast<Real>() - velocity).norm());
    strain_error = std::max(strain_error, (ps.deformation[p].cast<Real>() - Mat3::Identity()).norm());
    stress = std::max<Real>(stress, ps.stress[p].norm());
  }
  CHECK(sim.time() * velocity.norm() > h);
  CHECK(position_error < 1e-12 * h * 40);
  CHECK(velocity_error < 1e-12 * velocity.norm() * 40);
  CHECK(strain_error < 1e-12 * 40);
  CHECK(stress < 1e-12 * 1e6 * 40);  // E · round-off strain
  CHECK(sim.last_diagnostics().body_displacement[0].isApprox(sim.time() * velocity, 1e-12));
}

TEST_CASE("A uniform velocity gradient on the grid is reproduced at every particle", "[mpm][transfer]") {
  const auto shape = GENERATE(values(all_shapes));
  const Real h = 0.5e-3;
  std::mt19937 rng(11);
  std::uniform_real_distribution<Real> u(-1, 1);
  Mat3 A;
  for (int i = 0; i < 9; ++i) A(i) = u(rng) * 100;  // 1/s
  const Vec3 b(u(rng), u(rng), u(rng));
  PointSet points = block_points(h);
  for (auto& x : points.position) x += 0.3 * h * Eigen::Vector3d(u(rng), u(rng), u(rng));
  Simulation sim(points, block_body(), settings_for(shape, h));
  SimulationTestAccess::particles_to_grid(sim);
  SimulationTestAccess::set_grid_velocity(sim, [&](const Vec3& x) { return Vec3(A * x + b); });
  const auto g = SimulationTestAccess::gather_from_grid(sim);
  INFO("shape " << to_string(shape));
  Real v_error = 0, l_error = 0;
  for (size_t p = 0; p < sim.particles().size(); ++p) {
    v_error = std::max(v_error, (g.velocity[p] - (A * sim.particles().position[p] + b)).norm());
    l_error = std::max(l_error, (g.velocity_gradient[p] - A).norm());
  }
  CHECK(v_error < 1e-13 * (A.norm() * 1e-2 + b.norm()));
  CHECK(l_error < 1e-12 * A.norm());
}

TEST_CASE("A uniform-strain patch mapped through P2G and G2P is exact away from the surface", "[mpm][transfer]") {
  // Points placed symmetrically about every node (ppc 2): p_i / m_i = A x_i at interior
  // nodes, so interior particles recover L = A exactly.
  const auto shape = GENERATE(values(all_shapes));
  const Real h = 1e-3;
  Mat3 A;
  A << 3, -1, 0.5, 2, -4, 1, 0.25, 1.5, 2;  // 1/s
  const PointSet points = block_points(h);
  Simulation sim(points, block_body(), settings_for(shape, h));
  for (size_t p = 0; p < sim.particles().size(); ++p)
    sim.mutable_particles().velocity[p] = (A * sim.particles().position[p]).cast<ParticleReal>();
  SimulationTestAccess::particles_to_grid(sim);
  SimulationTestAccess::grid_update(sim, 1e-7);
  const auto g = SimulationTestAccess::gather_from_grid(sim);
  const Eigen::Vector3d lo = h * Eigen::Vector3d(-5, -3, 2), hi = h * Eigen::Vector3d(7, 7, 11);
  int interior = 0;
  Real l_error = 0;
  for (size_t p = 0; p < sim.particles().size(); ++p) {
    const Vec3& x = sim.particles().position[p];
    if (((x - lo).array() < 3 * h).any() || ((hi - x).array() < 3 * h).any()) continue;
    ++interior;
    l_error = std::max(l_error, (g.velocity_gradient[p] - A).norm());
  }
  INFO("shape " << to_string(shape));
  CHECK(interior > 100);
  CHECK(l_error < 1e-10 * A.norm());
}
