// DDMP's smoothed gradient on the grid (Paper A Eq. 4, ddmp_grid.hpp) against the
// per-particle modified gradient ∇̄S (Eq. 7, make_ddmp_stencil) it regroups: on a deformed,
// ragged block (free surfaces, cells partly filled, so Ω has holes and corners), the nodal
// forces after P2G and the velocity gradient L̄ at every particle from a nonlinear grid
// velocity agree to round-off.
#include <catch2/catch.hpp>

#include <map>
#include <memory>
#include <random>

#include "mpm/simulation.hpp"
#include "point_builders.hpp"

using namespace latmpm;
using namespace latmpm::mpm;
using namespace latmpm::mpm::test;

namespace {
// A 10×8×9-cell block at ppc 2 with a spherical hole and a fifth of its points dropped at
// random, jittered, with a random F (det > 0) and a random stress per point.
std::unique_ptr<Simulation> deformed_block(bool on_grid, unsigned seed) {
  const Real h = 1e-3;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(-1, 1);
  PointSet points = empty_point_set(h, 2);
  const Eigen::Vector3d centre = h * Eigen::Vector3d(2, 3, 6);
  add_points(points, h * Eigen::Vector3d(-3, -1, 2), h * Eigen::Vector3d(7, 7, 11), "block",
             [&](const Eigen::Vector3d& x) { return (x - centre).norm() > 2.5 * h && u(rng) > -0.6; });
  for (auto& x : points.position) x += 0.2 * h * Eigen::Vector3d(u(rng), u(rng), u(rng));
  Settings s;
  s.cell_size = h;
  s.shape_function = ShapeFunctionKind::ddmp;
  s.threads = 2;
  s.ddmp_on_grid = on_grid;
  auto sim = std::make_unique<Simulation>(points, std::vector<BodySettings>{deformable("block", elastic(1e6, 0.3, 1000))}, s);
  Particles& ps = sim->mutable_particles();
  for (size_t p = 0; p < ps.size(); ++p) {
    Mat3 F = Mat3::Identity();
    for (int i = 0; i < 9; ++i) F(i) += 0.2 * u(rng);
    if (F.determinant() < 0.2) F = Mat3::Identity();
    ps.deformation[p] = F;
    for (int c = 0; c < 6; ++c) ps.stress[p][c] = 1e5 * u(rng);
  }
  return sim;
}
}  // namespace

TEST_CASE("DDMP's force and velocity gradient on the grid equal the per-particle modified gradient",
          "[mpm][ddmp]") {
  const unsigned seed = GENERATE(3u, 17u);
  const auto reference_sim = deformed_block(false, seed), grid_sim = deformed_block(true, seed);
  Simulation &reference = *reference_sim, &grid = *grid_sim;
  REQUIRE(reference.particles().size() == grid.particles().size());
  reference.stage_particles_to_grid();
  grid.stage_particles_to_grid();

  // Nodal internal forces: the grid path allocates only the blocks of the particles' own
  // cells; any node it lacks must carry no force in the reference.
  std::map<std::array<int, 3>, Vec3> grid_force;
  for (const auto& n : grid.grid_nodes()) grid_force[n.index] = Vec3(n.lanes[4], n.lanes[5], n.lanes[6]);
  Real largest = 0, force_error = 0;
  size_t compared = 0;
  for (const auto& n : reference.grid_nodes()) {
    const Vec3 f(n.lanes[4], n.lanes[5], n.lanes[6]);
    const auto it = grid_force.find(n.index);
    const Vec3 g = it == grid_force.end() ? Vec3::Zero() : it->second;
    largest = std::max(largest, f.norm());
    force_error = std::max(force_error, (f - g).norm());
    compared += f.norm() > 0;
  }
  INFO("nodes with force " << compared << ", largest force " << largest << " N");
  REQUIRE(largest > 0);
  CHECK(force_error < 1e-12 * largest);

  // L̄ from a nonlinear grid velocity (nodal L_j on the grid, MUSL/USL's gather).
  auto field = [](const Vec3& x) {
    const Vec3 y = x * 1e3;  // in cells
    return Vec3(std::sin(y[1]) + y[0] * y[2], std::cos(y[0] + 0.3 * y[2]), y[1] * y[1] - y[0]);
  };
  reference.stage_set_grid_velocity(field);
  grid.stage_set_grid_velocity(field);
  const auto a = reference.gather_from_grid(), b = grid.gather_from_grid();
  Real largest_l = 0, l_error = 0, v_error = 0;
  for (size_t p = 0; p < a.velocity.size(); ++p) {
    REQUIRE(reference.particles().id[p] == grid.particles().id[p]);
    largest_l = std::max(largest_l, a.velocity_gradient[p].norm());
    l_error = std::max(l_error, (a.velocity_gradient[p] - b.velocity_gradient[p]).norm());
    v_error = std::max(v_error, (a.velocity[p] - b.velocity[p]).norm());
  }
  INFO("largest L " << largest_l << " 1/s");
  CHECK(l_error < 1e-12 * largest_l);
  CHECK(v_error < 1e-13);
}
