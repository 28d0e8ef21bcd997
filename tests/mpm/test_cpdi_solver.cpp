// CPDI1 as the solver's shape function (shape_cpdi.hpp, paper B Eq. 7): hexahedral domains
// with moved interior vertices, checked in the solver's own transfers against references
// that do not use the CPDI code: a linear grid velocity field (reproduced exactly by any
// complete shape function), the closed-form product of the solver's F updates under a
// rigid rotation, and the first axial mode of a free bar (period 2L/c).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/errors.hpp"
#include "hexmesh/hex_points.hpp"
#include "mpm/shape_cpdi.hpp"
#include "mpm/simulation.hpp"
#include "mpm/simulation_test_access.hpp"
#include "free_bar.hpp"
#include "point_builders.hpp"

using namespace latmpm;
using namespace latmpm::mpm;
using namespace latmpm::mpm::test;

namespace {

// A conforming mesh of n bricks of edge `size` from `lo`, interior vertices moved by up to
// `jitter`·size per axis; its CPDI1 points (hexmesh/hex_points.hpp: one per brick at its
// centroid with its exact volume) added to `ps` as `body`.
void add_hex_points(PointSet& ps, const Vec3& lo, const Eigen::Vector3i& n, Real size, Real jitter,
                    const std::string& body, uint32_t seed = 7) {
  const int b = add_body_name(ps, body);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(-jitter * size, jitter * size);
  auto index = [&](int i, int j, int k) { return (size_t(i) * size_t(n[1] + 1) + size_t(j)) * size_t(n[2] + 1) + size_t(k); };
  HexMesh mesh;
  mesh.nodes.resize(size_t(n[0] + 1) * size_t(n[1] + 1) * size_t(n[2] + 1));
  for (int i = 0; i <= n[0]; ++i)
    for (int j = 0; j <= n[1]; ++j)
      for (int k = 0; k <= n[2]; ++k) {
        Vec3 x = lo + size * Vec3(i, j, k);
        const bool interior = i > 0 && i < n[0] && j > 0 && j < n[1] && k > 0 && k < n[2];
        if (interior) x += Vec3(u(rng), u(rng), u(rng));
        mesh.nodes[index(i, j, k)] = x;
      }
  for (int i = 0; i < n[0]; ++i)
    for (int j = 0; j < n[1]; ++j)
      for (int k = 0; k < n[2]; ++k) {
        std::array<size_t, 8> element;  // gmsh order: face z−, counter-clockwise from (−,−), then face z+
        for (int c = 0; c < 8; ++c) {
          const int di = (c & 3) == 1 || (c & 3) == 2, dj = (c & 3) >= 2, dk = c >= 4;
          element[size_t(c)] = index(i + di, j + dj, k + dk);
        }
        mesh.elements.push_back(element);
      }
  const PointSet hex = hex_mesh_points(mesh, body, size);
  ps.position.insert(ps.position.end(), hex.position.begin(), hex.position.end());
  ps.volume.insert(ps.volume.end(), hex.volume.begin(), hex.volume.end());
  ps.half_size.insert(ps.half_size.end(), hex.half_size.begin(), hex.half_size.end());
  ps.domain_vertices.insert(ps.domain_vertices.end(), hex.domain_vertices.begin(), hex.domain_vertices.end());
  ps.body.insert(ps.body.end(), hex.size(), b);
  for (auto& [name, mask] : ps.tags) mask.insert(mask.end(), hex.size(), 0);
}

Settings cpdi_settings(Real h) {
  Settings s;
  s.cell_size = h;
  s.shape_function = ShapeFunctionKind::cpdi1;
  s.threads = 2;
  return s;
}

}  // namespace

namespace {

// Σ_I S_I = 1 gives Σ m_I = Σ m_p; Σ S_I x_I = x_p and Σ x_I ⊗ ∇S_I = I give v_p = A x_p + b
// and L_p = A from the nodal field v_I = A x_I + b — before and after the domains deformed
// (25 steps of A: stretches and shears of ~10–30 %). Returns the largest number of points
// whose domain reached past one cell (h) from its centre at one step (the wide stencils).
size_t check_linear_field(const Vec3& lo, const Eigen::Vector3i& n, Real size, Real h) {
  PointSet points = empty_point_set(h, 1);
  add_hex_points(points, lo, n, size, 0.2, "block");
  Simulation sim(points, {deformable("block", elastic(1e9, 0.3, 2000, MaterialKind::neo_hookean))}, cpdi_settings(h));
  Mat3 A;
  A << 300, -150, 80, 120, -250, 60, -40, 90, 200;  // 1/s
  const Vec3 b(0.2, -0.1, 0.3);                       // m/s
  auto field = [&](const Vec3& x) { return Vec3(A * x + b); };
  const Real dt = 4e-5;
  size_t most_wide = 0;
  for (int step = 0; step <= 25; ++step) {
    SimulationTestAccess::particles_to_grid(sim);
    Real mass = 0;
    size_t wide = 0;
    for (size_t p = 0; p < sim.particles().size(); ++p) {
      mass += sim.particles().mass[p];
      wide += make_cpdi_box_stencil(sim.particles(), p, h).wide;
    }
    most_wide = std::max(most_wide, wide);
    REQUIRE(SimulationTestAccess::grid_totals(sim).mass == Approx(mass).epsilon(1e-13));
    SimulationTestAccess::set_grid_velocity(sim, field);
    const SimulationTestAccess::Gathered g = SimulationTestAccess::gather_from_grid(sim);
    for (size_t p = 0; p < sim.particles().size(); ++p) {
      REQUIRE((g.velocity[p] - field(sim.particles().position[p])).norm() < 1e-12);
      REQUIRE((g.velocity_gradient[p] - A).norm() < 1e-9 * A.norm());
    }
    SimulationTestAccess::grid_to_particles(sim, dt);
  }
  // The domains did deform: F = exp-like product, far from I.
  CHECK((sim.particles().deformation[0] - Mat3::Identity()).norm() > 0.1);
  return most_wide;
}

}  // namespace

TEST_CASE("CPDI1 particles in the solver conserve mass and reproduce a linear velocity field", "[mpm][cpdi]") {
  // Bricks of 0.3 mm on h = 0.4 mm: every domain inside its stencil box.
  CHECK(check_linear_field(Vec3(0.05e-3, 0.1e-3, 0.02e-3), Eigen::Vector3i(6, 5, 4), 0.3e-3, 0.4e-3) == 0);
}

TEST_CASE("CPDI1 domains reaching past one cell conserve mass and reproduce a linear velocity field", "[mpm][cpdi]") {
  // Bricks of 1 mm on h = 0.4 mm reach 1.25 h from their centres (paper B's coarse meshes
  // on G4, and rim domains stretched by barrelling): their vertices' stencils lie outside
  // the bucket's box and go to the grid vertex by vertex (shape_cpdi.hpp). Bricks of 0.7 mm
  // mix both kinds in one bucket.
  CHECK(check_linear_field(Vec3(0.05e-3, 0.1e-3, 0.02e-3), Eigen::Vector3i(3, 3, 2), 1e-3, 0.4e-3) == 18);
  const size_t mixed = check_linear_field(Vec3(0.05e-3, 0.1e-3, 0.02e-3), Eigen::Vector3i(4, 3, 3), 0.7e-3, 0.4e-3);
  CHECK(mixed > 0);
  CHECK(mixed < 36);
}

TEST_CASE("A CPDI1 bar rotated by 90 degrees and back follows the solver's rigid-rotation update", "[mpm][cpdi]") {
  // Grid velocity ω × (x − c) for a quarter turn, then −ω × (x − c) back. Each step the
  // particle sees L = W exactly (the field is linear), so F = (I − Δt W)^n (I + Δt W)^n
  // = (I − Δt² W²)^n: unstrained to first order in Δt (strain n Δt² ω² = θ ω Δt). At 90°
  // the domain lies across the grid: a stencil that did not follow it (cpGIMP's diagonal
  // stretch) would lose its partition of unity there.
  const Real h = 0.4e-3, size = 0.2e-3;
  PointSet points = empty_point_set(h, 1);
  add_hex_points(points, Vec3(-1.2e-3, -0.2e-3, -0.2e-3), Eigen::Vector3i(12, 2, 2), size, 0.15, "bar");
  Simulation sim(points, {deformable("bar", elastic(1e9, 0.3, 2000, MaterialKind::neo_hookean))}, cpdi_settings(h));
  const int n = 4000;
  const Real omega = 100, dt = M_PI / 2 / (omega * n);  // rad/s; a quarter turn in n steps
  Mat3 W = Mat3::Zero();
  W(0, 1) = -omega, W(1, 0) = omega;  // about z through the origin
  std::vector<Vec3> x0 = sim.particles().position;
  std::vector<uint32_t> id0 = sim.particles().id;
  auto turn = [&](const Mat3& w) {
    for (int step = 0; step < n; ++step) {
      SimulationTestAccess::particles_to_grid(sim);
      SimulationTestAccess::set_grid_velocity(sim, [&](const Vec3& x) { return Vec3(w * x); });
      SimulationTestAccess::grid_to_particles(sim, dt);
    }
  };
  turn(W);
  {  // at 90°: F is the rotation to θ ω Δt, the bar lies along y
    const Mat3 F = sim.particles().deformation[0];
    Mat3 R = Mat3::Zero();
    R(0, 1) = -1, R(1, 0) = 1, R(2, 2) = 1;
    CHECK((F - R).norm() < 2 * M_PI / 2 * omega * dt);
  }
  turn(-W);
  Mat3 forward = Mat3::Identity();
  for (int step = 0; step < n; ++step) forward = (Mat3::Identity() + dt * W) * forward;
  Mat3 back = Mat3::Identity();
  for (int step = 0; step < n; ++step) back = (Mat3::Identity() - dt * W) * back;
  const Mat3 expected = back * forward;
  const Real strain = (expected.transpose() * expected - Mat3::Identity()).norm() / 2;
  INFO("Green strain of the round trip " << strain);
  CHECK(strain < 2 * M_PI / 2 * omega * dt);  // √2 θ ω Δt (two rotated axes)
  const Particles& ps = sim.particles();
  std::vector<Vec3> start(ps.size());
  for (size_t q = 0; q < ps.size(); ++q) start[id0[q]] = x0[q];
  for (size_t p = 0; p < ps.size(); ++p) {
    REQUIRE((ps.deformation[p] - expected).norm() < 1e-9);
    REQUIRE((ps.position[p] - expected * start[ps.id[p]]).norm() < 1e-9 * h);
  }
}

TEST_CASE("A free CPDI1 bar of distorted domains vibrates axially with the analytic period", "[mpm][cpdi]") {
  // First free–free mode, v = v0 cos(πx/L), period 2L/c, c = sqrt(E/ρ) with ν = 0 (a bar and
  // a dilatational wave travel alike). 80 × 2 × 2 domains, two per cell along the bar.
  const Real h = 1e-3, size = 0.5e-3, length = 40 * h, v0 = 0.01, young = 1e6, density = 1000;
  const Real c = std::sqrt(young / density), period = 2 * length / c;
  PointSet points = empty_point_set(h, 2);
  add_hex_points(points, Vec3(0, 0, 0), Eigen::Vector3i(80, 2, 2), size, 0.2, "bar");
  Simulation sim(points, {deformable("bar", elastic(young, 0, density))}, cpdi_settings(h));
  const BarRun run = run_first_axial_mode(sim, length, v0, 1.3 * period);
  INFO("period " << run.period << " s, expected " << period << " s; energy ratio " << run.energy_ratio);
  CHECK(std::abs(run.period - period) < 0.02 * period);
  CHECK(run.energy_ratio < 1.02);
  CHECK(run.energy_ratio > 0.9);
}

TEST_CASE("CPDI1 refuses point sets without domains", "[mpm][cpdi]") {
  const Real h = 0.4e-3;
  PointSet voxels = empty_point_set(h, 2);
  add_points(voxels, Vec3::Zero(), Vec3(0.8e-3, 0.8e-3, 0.8e-3), "block");
  CHECK_THROWS_AS(Simulation(voxels, {deformable("block", elastic(1e9, 0.3, 2000))}, cpdi_settings(h)), InputError);
}
