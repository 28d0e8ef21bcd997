// DDMP through the solver's passes on a deformed, ragged block (free surfaces, a hole,
// cells partly filled): the smoothed gradient on the grid (Paper A Eq. 4, ddmp_grid.hpp)
// equals the per-particle modified gradient ∇̄S (Eq. 7) it regroups, nodal forces and L̄
// to round-off; Eq. 8 holds next to the free surfaces (Σ_i f_i = 0,
// Σ_i x_i ⊗ f_i = −Σ_p V_p σ_p, and a linear velocity field gives its gradient exactly);
// small-mass nodes hand on their mass, momentum and force without loss, each share as its
// distribution defines it. Eq. 8 also with sub-points (shape_ddmp_subpoints.hpp).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <random>

#include "mpm/ddmp_small_mass.hpp"
#include "mpm/simulation.hpp"
#include "mpm/simulation_test_access.hpp"
#include "point_builders.hpp"

using namespace latmpm;
using namespace latmpm::mpm;
using namespace latmpm::mpm::test;

namespace {
// A 10×8×9-cell block at ppc 2 with a spherical hole and a fifth of its points dropped at
// random, jittered, with a random F (det > 0) and a random stress per point.
std::unique_ptr<Simulation> deformed_block(bool on_grid, unsigned seed, bool subpoints = false) {
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
  s.ddmp_subpoints = subpoints;
  if (!on_grid || subpoints) s.ddmp_stabilization = 0;  // grid form only (ddmp_stabilization.hpp)
  auto sim = std::make_unique<Simulation>(points, std::vector<BodySettings>{deformable("block", elastic(1e6, 0.3, 1000))}, s);
  Particles& ps = sim->mutable_particles();
  for (size_t p = 0; p < ps.size(); ++p) {
    Mat3 F = Mat3::Identity();
    for (int i = 0; i < 9; ++i) F(i) += 0.2 * u(rng);
    if (F.determinant() < 0.2) F = Mat3::Identity();
    ps.deformation[p] = F.cast<ParticleReal>();
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
  SimulationTestAccess::particles_to_grid(reference);
  SimulationTestAccess::particles_to_grid(grid);

  // Nodal internal forces: the grid path allocates only the blocks of the particles' own
  // cells; any node it lacks must carry no force in the reference.
  std::map<std::array<int, 3>, Vec3> grid_force;
  for (const auto& n : SimulationTestAccess::grid_nodes(grid)) grid_force[n.index] = Vec3(n.lanes[4], n.lanes[5], n.lanes[6]);
  Real largest = 0, force_error = 0;
  size_t compared = 0;
  for (const auto& n : SimulationTestAccess::grid_nodes(reference)) {
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
  SimulationTestAccess::set_grid_velocity(reference, field);
  SimulationTestAccess::set_grid_velocity(grid, field);
  const auto a = SimulationTestAccess::gather_from_grid(reference), b = SimulationTestAccess::gather_from_grid(grid);
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

TEST_CASE("DDMP's modified gradient satisfies Eq. 8 next to free surfaces, through the solver's passes",
          "[mpm][ddmp]") {
  // 0: per particle, 1: on the grid, 2: on the grid with sub-points (shape_ddmp_subpoints.hpp).
  const int variant = GENERATE(0, 1, 2);
  INFO("variant " << variant);
  const auto sim_ptr = deformed_block(variant > 0, 5, variant == 2);
  Simulation& sim = *sim_ptr;
  const Real h = sim.settings().cell_size;
  SimulationTestAccess::particles_to_grid(sim);
  // Σ_i f_i = −Σ_p V_p σ_p Σ_i ∇̄S_i = 0; Σ_i f_i ⊗ x_i = −Σ_p V_p σ_p Σ_i ∇̄S_i ⊗ x_i = −Σ_p V_p σ_p.
  Vec3 total = Vec3::Zero();
  Mat3 moment = Mat3::Zero();
  Real largest = 0;
  for (const auto& n : SimulationTestAccess::grid_nodes(sim)) {
    const Vec3 f(n.lanes[4], n.lanes[5], n.lanes[6]);
    const Vec3 x = h * Vec3(n.index[0], n.index[1], n.index[2]);
    total += f;
    moment += f * x.transpose();
    largest = std::max(largest, f.norm());
  }
  const Particles& ps = sim.particles();
  Mat3 expected = Mat3::Zero();
  for (size_t p = 0; p < ps.size(); ++p) {
    const SymTensor s = ps.stress[p].cast<Real>();
    Mat3 sigma;
    sigma << s[0], s[5], s[4], s[5], s[1], s[3], s[4], s[3], s[2];
    expected -= ps.volume0[p] * ps.jacobian(p) * sigma;
  }
  INFO("largest nodal force " << largest << " N");
  CHECK(total.norm() < 1e-12 * largest * std::sqrt(Real(ps.size())));
  CHECK((moment - expected).norm() < 1e-11 * expected.norm());
  // A linear velocity field on every node: L̄ = A at every particle, surface ones included.
  Mat3 A;
  A << 3, -1, 2, 0.5, 4, -2, 1, 1, -3;
  const Vec3 b(0.2, -0.1, 0.3);
  SimulationTestAccess::set_grid_velocity(sim, [&](const Vec3& x) { return Vec3(A * x + b); });
  const auto g = SimulationTestAccess::gather_from_grid(sim);
  Real l_error = 0;
  for (const Mat3& L : g.velocity_gradient) l_error = std::max(l_error, (L - A).norm());
  CHECK(l_error < 1e-11 * A.norm());
  if (variant == 1) {
    // The stabilization (ddmp_stabilization.hpp) sees no difference between the plain and
    // the modified gradient of a linear field, so σ_s stays zero, surface points included;
    // a node-to-node zig-zag along z, which the smoothed part does not see, loads it.
    const Real beta = sim.settings().ddmp_stabilization, dt = 1e-6;
    REQUIRE(beta > 0);
    const Real modulus = beta * 1e6 * (1 - 0.3) / ((1 + 0.3) * (1 - 2 * 0.3));  // β(λ + 2μ), Pa
    auto largest_stabilization_stress = [&] {
      Real s = 0;
      for (const auto& t : sim.particles().ddmp_stabilization_stress) s = std::max(s, Real(t.cast<Real>().cwiseAbs().maxCoeff()));
      return s;
    };
    SimulationTestAccess::grid_to_particles(sim, dt);
    CHECK(largest_stabilization_stress() < 1e-10 * modulus * dt * A.norm());
    const Real c = 0.01;  // m/s
    SimulationTestAccess::set_grid_velocity(
        sim, [&](const Vec3& x) { return Vec3(0, 0, (int(std::lround(x[2] / h)) % 2 ? c : -c)); });
    SimulationTestAccess::grid_to_particles(sim, dt);
    // Plain gradient ∂v_z/∂z = ±2c/h, of which (1 − α) ≥ 0.77 is missing from L̄.
    CHECK(largest_stabilization_stress() > 0.5 * modulus * dt * 2 * c / h);
  }
}

TEST_CASE("DDMP's small-mass nodes hand on their mass, momentum and force and read their velocity back",
          "[mpm][ddmp]") {
  const auto sim_ptr = deformed_block(true, 9);
  Simulation& sim = *sim_ptr;
  Particles& ps = sim.mutable_particles();
  std::mt19937 rng(4);
  std::uniform_real_distribution<Real> u(-1, 1);
  for (auto& v : ps.velocity) v = Vec3(u(rng), u(rng), u(rng)).cast<ParticleReal>();
  SimulationTestAccess::particles_to_grid(sim);
  const auto before = SimulationTestAccess::grid_totals(sim);
  Vec3 force = Vec3::Zero();
  size_t small = 0, empty_with_force = 0;
  const Real small_mass = sim.settings().ddmp_small_mass_fraction * 1000 * std::pow(sim.settings().cell_size, 3);
  for (const auto& n : SimulationTestAccess::grid_nodes(sim)) {
    force += Vec3(n.lanes[4], n.lanes[5], n.lanes[6]);
    small += n.lanes[0] < small_mass;
    empty_with_force += n.lanes[0] == 0 && Vec3(n.lanes[4], n.lanes[5], n.lanes[6]).norm() > 0;
  }
  INFO(small << " nodes below the small mass, " << empty_with_force << " without mass but with force");
  REQUIRE(empty_with_force > 0);  // the smoothed force reaches beyond the material
  const Real dt = 1e-7;
  SimulationTestAccess::grid_update(sim, dt);
  const auto after = SimulationTestAccess::grid_totals(sim);
  // Mass is handed on, not lost; momentum changes by dt · Σ f (no gravity, no held nodes).
  CHECK(after.mass == Approx(before.mass).epsilon(1e-14));
  const Real momentum_scale = before.mass * 1;  // kg · (speeds ≤ √3 m/s)
  CHECK((after.momentum - before.momentum - dt * force).norm() < 1e-13 * momentum_scale);
  // Every node left with mass is above the small mass, or has no sizeable neighbour.
  Real small_left = 0;
  for (const auto& n : SimulationTestAccess::grid_nodes(sim))
    if (n.lanes[0] > 0 && n.lanes[0] < small_mass) small_left += n.lanes[0];
  CHECK(small_left < 1e-3 * before.mass);
}

// The remembered distributions (ddmp_small_mass.hpp) are a pure function of the neighbourhood
// pattern, so the memo may be emptied between steps: past its limit it is, before the step's
// pointers into it are taken (a crushed lattice kept adding patterns until the QUICK DDMP
// impact held 1.8 GB). Two twin blocks step alike, one after the memo was overfilled; then
// both again, each after the memo was emptied since its last step (a node's distribution of
// the last step is reused only while the memo that holds it stands).
TEST_CASE("DDMP's remembered distributions stay bounded and do not change a step", "[mpm][ddmp]") {
  using namespace ddmp_grid_detail;
  const auto a = deformed_block(true, 11), b = deformed_block(true, 11);
  for (Simulation* sim : {a.get(), b.get()}) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<Real> u(-1, 1);
    for (auto& v : sim->mutable_particles().velocity) v = Vec3(u(rng), u(rng), u(rng)).cast<ParticleReal>();
  }
  // Patterns of up to 14 sizeable neighbours (their fits are whatever they are): past the limit.
  const auto overfill = [] {
    for (size_t i = 0; distribution_memo().size() <= distribution_memo_limit + 100; ++i) {
      NeighbourPattern pattern;
      pattern.bits[0] = uint64_t(i) << 20;
      remembered_distribution(pattern);
    }
  };
  const auto count_differences = [&] {
    const Particles &pa = a->particles(), &pb = b->particles();
    size_t differ = 0;
    for (size_t p = 0; p < pa.size(); ++p)
      differ += pa.position[p] != pb.position[p] || pa.velocity[p] != pb.velocity[p] || pa.stress[p] != pb.stress[p] ||
                pa.deformation[p] != pb.deformation[p];
    return differ;
  };
  a->step();
  overfill();
  b->step();
  CHECK(distribution_memo().size() <= distribution_memo_limit);
  CHECK(count_differences() == 0);
  a->step();  // the memo was emptied in b's step
  overfill();
  b->step();
  CHECK(distribution_memo().size() <= distribution_memo_limit);
  CHECK(count_differences() == 0);
}

// MaskHalo::within<R>, the bit tricks behind the find's "a node with mass within one cell"
// and its "a changed mask within reach", against the definition: node (i, j, k) of the
// block is set when a halo bit within R nodes of it along every axis is.
TEST_CASE("DDMP's mask halo dilation equals the neighbourhood test node by node", "[mpm][ddmp]") {
  using namespace ddmp_grid_detail;
  std::mt19937_64 rng(17);
  for (int round = 0; round < 200; ++round) {
    MaskHalo halo;
    const int sparsity = round % 4;  // dense to a few bits
    for (auto& row : halo.row)
      for (auto& bits : row) {
        uint64_t r = rng();
        for (int s = 0; s < sparsity; ++s) r &= rng();
        bits = uint8_t(r);
      }
    const auto expected = [&](int R) {
      uint64_t out = 0;
      for (int i = 0; i < bw; ++i)
        for (int j = 0; j < bw; ++j)
          for (int k = 0; k < bw; ++k) {
            bool any = false;
            for (int x = -R; x <= R; ++x)
              for (int y = -R; y <= R; ++y)
                for (int z = -R; z <= R; ++z) any |= (halo.row[i + reach + x][j + reach + y] >> (k + reach + z)) & 1;
            out |= uint64_t(any) << ((i * bw + j) * bw + k);
          }
      return out;
    };
    CHECK(halo.within<1>() == expected(1));
    CHECK(halo.within<2>() == expected(2));
  }
}

// The find keeps its last decisions node by node where nothing within reach of a node changed
// (find_ddmp_small_mass_nodes): two twin blocks flying apart at up to 10 m/s — points cross
// cells, nodes fall below the small mass and rise above it every step — one finding from
// scratch before every step, step alike bit for bit.
TEST_CASE("DDMP's find reusing the last step's decisions equals a find from scratch", "[mpm][ddmp]") {
  const auto a = deformed_block(true, 13), b = deformed_block(true, 13);
  for (Simulation* sim : {a.get(), b.get()}) {
    std::mt19937 rng(6);
    std::uniform_real_distribution<Real> u(-10, 10);
    for (auto& v : sim->mutable_particles().velocity) v = Vec3(u(rng), u(rng), u(rng)).cast<ParticleReal>();
  }
  const Real h = a->settings().cell_size;
  const std::vector<Vec3> start = a->particles().position;
  for (int step = 0; step < 40; ++step) {
    SimulationTestAccess::forget_last_ddmp_find(*b);
    a->step();
    b->step();
    const Particles &pa = a->particles(), &pb = b->particles();
    size_t differ = 0;
    for (size_t p = 0; p < pa.size(); ++p)
      differ += pa.position[p] != pb.position[p] || pa.velocity[p] != pb.velocity[p] || pa.stress[p] != pb.stress[p];
    INFO("step " << step);
    REQUIRE(differ == 0);
  }
  // The points moved cells (up to 10 m/s over the run), so the masks changed on the way.
  Real moved = 0;
  for (size_t p = 0; p < start.size(); ++p) moved = std::max(moved, Real((a->particles().position[p] - start[p]).norm()));
  CHECK(moved > h);
}

// A small-mass node's distribution (ddmp_small_mass.hpp, fit_distribution) reads constant and
// linear fields back exactly — Σ_i C_li = 1, Σ_i C_li d_i = 0 — from its nearest sizeable
// neighbours (|d|₁ ≤ 2) where they span 3D, and from all 124 within two cells only where they
// do not. Checked on a node inside the material, one outside a flat face, one outside a
// corner, and 2,000 random neighbourhoods, against those definitions.
TEST_CASE("DDMP's distributions are exact for linear fields over the nearest neighbours that span them",
          "[mpm][ddmp]") {
  using namespace latmpm::mpm::ddmp_grid_detail;
  const auto& offsets = neighbour_offsets();
  const auto check = [&](const NeighbourPattern& pattern) {
    const DistributionFit fit = fit_distribution(pattern);
    const DdmpDistribution& d = DistributionStorage(pattern, fit).distribution();
    uint32_t sizeable = 0;
    for (const Offset& o : offsets) sizeable += pattern.sizeable(o);
    REQUIRE((d.count == 0) == (sizeable == 0));
    if (d.count == 0) return fit;
    // The receivers by their definition: sizeable, and |d|₁ ≤ 2 unless the fit is the wide one.
    const auto receiver = [&](const Offset& o) {
      const bool nearest = std::abs(o.x) + std::abs(o.y) + std::abs(o.z) <= 2;
      return pattern.sizeable(o) && (nearest || fit.receivers == Receivers::within_two_cells);
    };
    Real sum = 0;
    Vec3 first = Vec3::Zero();
    uint32_t s = 0;
    for (const Offset& o : offsets)
      if (receiver(o)) {
        REQUIRE(s < d.count);
        REQUIRE(d.steps[s] == box_index_step(o.x, o.y, o.z));
        sum += d.shares[s];
        first += d.shares[s] * Vec3(o.x, o.y, o.z);
        ++s;
      }
    CHECK(s == d.count);
    CHECK(sum == Approx(1).epsilon(1e-12));
    const bool nearest_span = fit_over(pattern, Receivers::nearest).spans;
    const bool all_span = fit_over(pattern, Receivers::within_two_cells).spans;
    // The nearest wherever they span; linear exactness wherever the receivers span (a node
    // with mass of its own may instead take the weighted mean, never a negative share).
    CHECK((fit.receivers == Receivers::nearest) == nearest_span);
    const bool mean = fit.coefficients[1] == 0 && fit.coefficients[2] == 0 && fit.coefficients[3] == 0;
    if (pattern.has(own_mass_bit) && mean)
      for (uint32_t q = 0; q < d.count; ++q) CHECK(d.shares[q] > 0);
    else if (all_span)
      CHECK(first.norm() < 1e-12);
    return fit;
  };
  // Inside the material: every neighbour sizeable — the 24 nearest.
  NeighbourPattern inside;
  for (const Offset& o : offsets) inside.set(box_bit(o.x, o.y, o.z));
  inside.set(own_mass_bit);
  CHECK(check(inside).receivers == Receivers::nearest);
  CHECK(DistributionStorage(inside, fit_distribution(inside)).distribution().count == 24);
  // One cell above a flat face z = 0 (sizeable at dz = −1, −2): the two layers below along the
  // normal and the four beside the first, 6 receivers instead of the 50 sizeable within two cells.
  NeighbourPattern face;
  for (const Offset& o : offsets)
    if (o.z < 0) face.set(box_bit(o.x, o.y, o.z));
  CHECK(check(face).receivers == Receivers::nearest);
  CHECK(DistributionStorage(face, fit_distribution(face)).distribution().count == 6);
  // Outside a corner (sizeable where x, y, z < 0): none within |d|₁ ≤ 2, so all within two cells.
  NeighbourPattern corner;
  for (const Offset& o : offsets)
    if (o.x < 0 && o.y < 0 && o.z < 0) corner.set(box_bit(o.x, o.y, o.z));
  CHECK(check(corner).receivers == Receivers::within_two_cells);
  CHECK(DistributionStorage(corner, fit_distribution(corner)).distribution().count == 8);
  // Random neighbourhoods, sparse to dense, with and without mass of their own.
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> u(0, 1);
  size_t nearest = 0, wide = 0;
  for (int t = 0; t < 2000; ++t) {
    NeighbourPattern p;
    const Real density = u(rng);
    for (const Offset& o : offsets)
      if (u(rng) < density) p.set(box_bit(o.x, o.y, o.z));
    if (u(rng) < 0.5) p.set(own_mass_bit);
    (check(p).receivers == Receivers::nearest ? nearest : wide) += 1;
  }
  INFO(nearest << " nearest, " << wide << " within two cells");
  CHECK(nearest > 0);
  CHECK(wide > 0);
}

// The hand-on (move_ddmp_small_mass_lanes) against its definition: every node l that hands on
// adds C_li times its lanes to each of its receivers i — the sizeable nodes of its pattern
// among the nearest or all within two cells, its distribution's shares in neighbour_offsets
// order (their values are the linear-fields test's above) — and keeps none. On a grid of a
// lumpy blob, a one-node-thick plate (the weighted mean) and scattered sizeable nodes (fits
// over all within two cells), with nodes below the small mass inside and massless nodes with
// force around: the moved lanes equal those of the definition applied node by node, to
// round-off, for all seven lanes and for the force alone.
TEST_CASE("DDMP's hand-on gives every receiver the shares its sources' distributions define", "[mpm][ddmp]") {
  using namespace latmpm::mpm::ddmp_grid_detail;
  const Real small_mass = 0.1;
  std::mt19937 rng(23);
  std::uniform_real_distribution<Real> u(0, 1);
  SparseGrid grid;
  std::vector<uint64_t> keys;
  for (int bx = -1; bx <= 3; ++bx)
    for (int by = -1; by <= 3; ++by)
      for (int bz = -1; bz <= 2; ++bz) keys.push_back(SparseGrid::block_key(bx, by, bz));
  std::sort(keys.begin(), keys.end());
  grid.set_active_blocks(keys);
  // Mass: a blob of radius 4–6 nodes around (5, 5, 4), a plate z = 9 for x, y in 1 … 6, and
  // sizeable nodes at random in 9 … 13 × 1 … 13 × −2 … 8; below the small mass at random in
  // the blob's outermost layer; lanes 1–6 random where there is mass, force on every node near it.
  const auto blob_radius = [](Real x, Real y, Real z) {
    return 5 + std::sin(x) * std::cos(1.7 * y) + 0.5 * std::sin(2.3 * z);
  };
  for (int i = -4; i < 16; ++i)
    for (int j = -4; j < 16; ++j)
      for (int k = -4; k < 12; ++k) {
        Real* node = grid.node(i, j, k);
        const Vec3 x(i - 5, j - 5, k - 4);
        const Real r = x.norm(), radius = blob_radius(x[0], x[1], x[2]);
        Real m = 0;
        if (r < radius - 1) m = 0.1 + u(rng);
        else if (r < radius) m = u(rng) < 0.5 ? 0.1 * u(rng) : 0.1 + u(rng);
        if (k == 9 && i >= 1 && i <= 6 && j >= 1 && j <= 6) m = 0.1 + u(rng);
        if (i >= 9 && i <= 13 && j >= 1 && j <= 13 && k >= -2 && k <= 8 && u(rng) < 0.3) m = 0.1 + u(rng);
        node[lane::mass] = m;
        for (int c = 1; c < 4; ++c) node[c] = m > 0 ? u(rng) - 0.5 : 0;
        for (int c = 4; c < 7; ++c) node[c] = r < radius + 2 || m > 0 || k >= 8 ? u(rng) - 0.5 : 0;
      }
  DdmpNodalValues nv;
  prepare_ddmp_nodal_values(grid, nv);
  find_ddmp_small_mass_nodes(grid, small_mass, nv);
  const auto run = [&](auto first, auto count) {
    constexpr int First = decltype(first)::value, Count = decltype(count)::value;
    SparseGrid moved = grid;
    move_ddmp_small_mass_lanes<First, Count>(moved, nv);
    // The definition, node by node, on a copy.
    SparseGrid expected = grid;
    size_t sources = 0, wide = 0, means = 0, shares = 0;
    Real scale = 0;
    for (size_t b = 0; b < grid.block_count(); ++b)
      for (int n = 0; n < SparseGrid::nodes_per_block; ++n) {
        const Real* node = grid.block(b) + n * lane::count;
        for (int c = 0; c < 7; ++c) scale = std::max(scale, std::abs(node[c]));
        if (!((nv.handing[b] >> n) & 1)) continue;
        const DdmpDistribution& d = *nv.distributions[b * SparseGrid::nodes_per_block + size_t(n)];
        const DistributionFit fit = fit_distribution(d.pattern);
        const bool nearest_only = fit.receivers == Receivers::nearest;
        const auto at = grid.coord(b);
        const int l[3] = {at[0] * bw + (n >> 4), at[1] * bw + ((n >> 2) & 3), at[2] * bw + (n & 3)};
        uint32_t s = 0;
        for (const Offset& o : neighbour_offsets()) {
          const bool nearest = std::abs(o.x) + std::abs(o.y) + std::abs(o.z) <= 2;
          if (!d.pattern.sizeable(o) || (nearest_only && !nearest)) continue;
          Real* receiver = expected.node(l[0] + o.x, l[1] + o.y, l[2] + o.z);
          REQUIRE(receiver != nullptr);
          REQUIRE(receiver[lane::mass] >= small_mass);
          for (int c = First; c < First + Count; ++c) receiver[c] += d.shares[s] * node[c];
          ++s;
        }
        REQUIRE(s == d.count);
        Real* source = expected.block(b) + n * lane::count;
        for (int c = First; c < First + Count; ++c) source[c] = 0;
        ++sources, shares += s, wide += !nearest_only;
        means += fit.coefficients[1] == 0 && fit.coefficients[2] == 0 && fit.coefficients[3] == 0;
      }
    INFO(sources << " sources, " << shares << " shares, " << wide << " over all within two cells, " << means
                 << " weighted means");
    CHECK(sources > 500);
    CHECK(wide > 20);
    CHECK(means > 10);
    Real worst = 0;
    for (size_t b = 0; b < grid.block_count(); ++b)
      for (int q = 0; q < SparseGrid::reals_per_block; ++q)
        worst = std::max(worst, std::abs(moved.block(b)[q] - expected.block(b)[q]));
    // The hand-on adds a receiver's shares in another order than this loop (tile by tile): sums
    // of at most a few dozen terms no larger than `scale` differ in their last bits only.
    CHECK(worst < 1e-14 * scale * 30);
  };
  run(std::integral_constant<int, lane::mass>{}, std::integral_constant<int, 7>{});
  run(std::integral_constant<int, lane::force>{}, std::integral_constant<int, 3>{});
}
