// Grid contact between the struts of one lattice body, partitioned by the voxelizer into
// strut groups (voxelize/strut_partition.hpp, docs/contact.md "Strut groups of a lattice"):
// two struts lying against each other slide along each other (one field: they stick), and a joint
// bonded through its untagged zone carries tension like the single-field body (the same
// bar with its joint split between two groups flies apart instead).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>

#include "mpm/simulation.hpp"
#include "point_builders.hpp"
#include "voxelize/strut_partition.hpp"
#include "voxelize/voxelize.hpp"

using namespace latmpm;
using namespace latmpm::mpm;
using namespace latmpm::mpm::test;

namespace {
constexpr Real E = 1e7, rho = 1000, h = 0.5e-3, r = 1e-3;

// The points of a strut graph of radius-r struts, with strut groups in at most 4 colours.
PointSet strut_points(const std::vector<Eigen::Vector3d>& nodes, const std::vector<std::pair<int, int>>& struts) {
  StrutGraph graph;
  graph.name = "test";
  graph.nodes = nodes;
  for (const auto& [a, b] : struts) graph.struts.push_back({a, b, r});
  VoxelizeOptions options;
  options.cell_size = h;
  options.ppc = 2;
  options.strut_groups = 4;
  return voxelize_strut_graph(graph, options).points;
}

Settings settings(bool contact) {
  Settings s;
  s.cell_size = h;
  s.threads = 2;
  s.field_contact.enabled = contact;
  if (contact) s.field_contact.groups = {std::string(strut_group_tag_prefix) + "*"};
  return s;
}

Real strain_energy_peak(Simulation& sim, Real end) {
  Real peak = 0;
  while (sim.time() < end) {
    sim.step();
    peak = std::max(peak, Real(sim.last_diagnostics().strain_energy));
  }
  return peak;
}
}  // namespace

TEST_CASE("Two struts of one lattice body lying against each other part freely with strut groups and stick with one field",
          "[mpm][field_contact][strut_groups]") {
  // A U of one body: two parallel arms 12 mm long, one on the other (their surfaces touch
  // along a line, as struts folded onto each other do), joined at one end by a short post.
  // The arms swing apart (v_z = ∓v0 (x − 2 mm)/12 mm). Reference: one arm alone on the post
  // (an L) swings as a cantilever. Strut groups: each arm as if alone, but for the bonded
  // zone around the joints (docs/contact.md); one field: glued where they touch, in
  // tension, their opposite momenta cancel.
  const Real z1 = 2e-3 + 2 * r;
  const std::vector<Eigen::Vector3d> nodes{{2e-3, 2e-3, 2e-3}, {14e-3, 2e-3, 2e-3}, {2e-3, 2e-3, z1}, {14e-3, 2e-3, z1}};
  constexpr Real v0 = 1, end = 1.2e-3;
  auto swing = [&](const PointSet& points, bool contact) {
    Simulation sim(points, {deformable("lattice", elastic(E, 0.3, rho))}, settings(contact));
    Particles& ps = sim.mutable_particles();
    for (size_t i = 0; i < ps.size(); ++i) {
      const Vec3& x = ps.position[i];
      if (x[0] > 3e-3) ps.velocity[i] = ParticleVec3(0, 0, (x[2] < 0.5 * (2e-3 + z1) ? -v0 : v0) * (x[0] - 2e-3) / 12e-3);
    }
    sim.run_until(end);
    Real tip[2] = {0, 0}, count[2] = {0, 0};  // mean z displacement of each arm's tip (x > 12 mm)
    const Particles& q = sim.particles();
    for (size_t i = 0; i < q.size(); ++i) {
      const Eigen::Vector3d& x0 = points.position[q.id[i]];
      const int arm = x0[2] < 0.5 * (2e-3 + z1) ? 0 : 1;
      if (x0[0] > 12e-3) tip[arm] += q.position[i][2] - x0[2], count[arm] += 1;
    }
    return std::pair<Real, Real>{tip[0] / count[0], count[1] > 0 ? tip[1] / count[1] : 0};
  };
  const PointSet u = strut_points(nodes, {{0, 1}, {0, 2}, {2, 3}});
  const PointSet l = strut_points(nodes, {{0, 1}, {0, 2}});
  const Real alone = -swing(l, false).first;
  const auto [groups_lower, groups_upper] = swing(u, true);
  const auto [single_lower, single_upper] = swing(u, false);
  REQUIRE(alone > 0.3e-3);  // it swung
  CHECK(groups_upper == Approx(-groups_lower).epsilon(0.05));  // symmetric, opposite
  CHECK(-groups_lower > 0.8 * alone);  // parted, not stuck (measured 0.82: the arms touch up to the joint zone)
  CHECK(single_upper - single_lower < 0.25 * (groups_upper - groups_lower));  // glued
}

TEST_CASE("A joint bonded through its untagged zone carries tension like the single-field body",
          "[mpm][field_contact][strut_groups]") {
  // A straight bar of two collinear struts (8 mm each, meeting at node 1) whose halves are
  // pulled apart at ±v0: each half is a bar clamped at the joint, so its kinetic energy
  // turns into strain energy within a wave transit (L/c ≈ 0.1 ms). The two struts get
  // different colours (they share a node); the joint zone is untagged and bonds them.
  PointSet points = strut_points({{2e-3, 2e-3, 2e-3}, {10e-3, 2e-3, 2e-3}, {18e-3, 2e-3, 2e-3}}, {{0, 1}, {1, 2}});
  REQUIRE(points.tags.count(strut_group_tag(1)));
  constexpr Real v0 = 1, end = 0.25e-3;
  auto run = [&](const PointSet& p, Settings s) {
    Simulation sim(p, {deformable("lattice", elastic(E, 0.0, rho))}, s);
    Particles& ps = sim.mutable_particles();
    Real kinetic = 0;
    for (size_t i = 0; i < ps.size(); ++i) {
      ps.velocity[i] = ParticleVec3(ps.position[i][0] < 10e-3 ? -v0 : v0, 0, 0);
      kinetic += 0.5 * ps.mass[i] * v0 * v0;
    }
    return strain_energy_peak(sim, end) / kinetic;
  };
  const Real bonded = run(points, settings(true));
  const Real single = run(points, settings(false));
  CHECK(single > 0.8);                                   // the reference: the halves are held at the joint
  CHECK(bonded == Approx(single).epsilon(0.02));         // bonded through the joint zone: the same
  // Control: the joint split between the two groups (every point tagged, by side) is not
  // bonded: the halves part without stretching.
  tag_points(points, "left", [&](size_t i) { return points.position[i][0] < 10e-3; });
  tag_points(points, "right", [&](size_t i) { return points.position[i][0] >= 10e-3; });
  Settings split = settings(true);
  split.field_contact.groups = {"left", "right"};
  CHECK(run(points, split) < 0.1 * single);
}
