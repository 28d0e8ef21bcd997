// Column buckling (Paper A Sec. 4) at coarse resolution: an imperfect column, clamped to a
// fixed base and to a driven top plate that cannot rotate, carries a peak load close to the
// Euler load of a clamped–clamped column, P = π² E I / (K L)², K = 0.5.
//
// Boundary conditions as simulated: the base's points (z < 0) touch the grid nodes up to the
// plane z = 0 and the top plate's points (z > L) those down to z = L. Every node of those
// planes takes the prescribed velocity, so the column's end sections neither move sideways
// nor rotate: clamped–clamped between z = 0 and z = L.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "mpm/simulation.hpp"
#include "point_builders.hpp"

using namespace latmpm;
using namespace latmpm::mpm;
using namespace latmpm::mpm::test;

TEST_CASE("An imperfect clamped column carries a peak load near the Euler load", "[mpm][buckling]") {
  // Paper A Sec. 4: t = 2.4 mm, L = 16 mm, E = 10 MPa, ν = 0.4, ρ = 6 ρ0 = 6300 kg/m³,
  // top driven down at 100 mm/s, imperfection u0(z) = a sin(πz/L), a = 0.02 L.
  const Real t = 2.4e-3, L = 16e-3, E = 10e6, nu = 0.4, rho = 6300, speed = 0.1, a = 0.02 * L;
  const Real h = 0.4e-3;  // coarse: 6 cells across, 40 along
  const int ppc = 2;
  const Real r = t / 2;
  auto in_disc = [&](const Eigen::Vector3d& x) { return x[0] * x[0] + x[1] * x[1] <= r * r; };
  PointSet points = empty_point_set(h, ppc);
  add_points(points, Eigen::Vector3d(-r, -r, 0), Eigen::Vector3d(r, r, L), "column", in_disc);
  for (auto& x : points.position) x[0] += a * std::sin(M_PI * x[2] / L);
  add_points(points, Eigen::Vector3d(-r, -r, -h), Eigen::Vector3d(r, r, 0), "base", in_disc);
  add_points(points, Eigen::Vector3d(-r, -r, L), Eigen::Vector3d(r, r, L + h), "plate", in_disc);

  Settings s;
  s.cell_size = h;
  s.shape_function = ShapeFunctionKind::ugimp;
  s.threads = 2;
  Simulation sim(points,
                 {deformable("column", elastic(E, nu, rho)), rigid("base", BodyRole::fixed, Vec3::Zero(), rho),
                  rigid("plate", BodyRole::driven, Vec3(0, 0, -speed), rho)},
                 s);

  const Real I = M_PI * std::pow(t, 4) / 64;
  const Real euler = M_PI * M_PI * E * I / std::pow(0.5 * L, 2);  // K = 0.5: 2.51 N

  // Load = −(plate reaction)_z, averaged over 0.8 ms — one period of the column's axial
  // ringing, 2L/sqrt(E/ρ) — so the peak is the quasi-static one, not a wave's overshoot.
  const Real window = 2 * L / std::sqrt(E / rho);
  std::vector<Real> times, loads, base_loads;
  sim.add_observer([&](const Simulation&, const StepDiagnostics& d) {
    times.push_back(d.time);
    loads.push_back(-d.reaction[2][2] * d.dt);
    base_loads.push_back(d.reaction[1][2] * d.dt);
  });
  // Shortening 1.4 mm (8.75 % of L), 1.6 times the elastic shortening at the Euler load
  // (P/(EA) L = 0.89 mm): the imperfect column's load has levelled off by then.
  const Real end = 1.4e-3 / speed;
  sim.run_until(end);

  // Moving averages of load (impulse per window / window).
  Real peak = 0, base_peak = 0, peak_time = 0;
  size_t first = 0;
  Real impulse = 0, base_impulse = 0;
  for (size_t i = 0; i < times.size(); ++i) {
    impulse += loads[i];
    base_impulse += base_loads[i];
    while (times[i] - times[first] > window) impulse -= loads[first], base_impulse -= base_loads[first], ++first;
    if (times[i] < window) continue;
    const Real span = times[i] - (first > 0 ? times[first - 1] : 0);
    if (impulse / span > peak) peak = impulse / span, peak_time = times[i];
    base_peak = std::max(base_peak, base_impulse / span);
  }
  INFO("Euler load (K = 0.5) " << euler << " N; peak plate load " << peak << " N at shortening "
                               << peak_time * speed * 1e3 << " mm; peak base load " << base_peak << " N; "
                               << sim.particles().size() << " points, " << sim.step_count() << " steps");
  CHECK(std::abs(peak - euler) < 0.15 * euler);
  CHECK(std::abs(base_peak - euler) < 0.15 * euler);
  // It buckled: the mid-height section moved sideways by more than the imperfection.
  Real mid_shift = 0;
  int mid_count = 0;
  for (size_t p = 0; p < sim.particles().size(); ++p)
    if (sim.particles().body[p] == 0 && std::abs(sim.particles().position[p][2] - L / 2) < h)
      mid_shift += sim.particles().position[p][0] - points.position[sim.particles().id[p]][0], ++mid_count;
  CHECK(std::abs(mid_shift / mid_count) > a);
}

namespace {
// Paper A's buckled column at 0.4 mm (h = 0.4 mm, 2 ppc, 4 cells across): t = 1.6 mm,
// L = 16 mm, a = 0.02 L, ν = 0.4, ρ = 6 ρ0, 100 mm/s, USL, plates two cells thick; the driven
// plate's mean load from `from` to `travel` (N). square: a square section of the same width.
Real buckled_column_plateau(ShapeFunctionKind shape, Real stabilization, bool square, Real travel, Real from) {
  const Real t = 1.6e-3, L = 16e-3, E = 10e6, nu = 0.4, rho = 6300, speed = 0.1, a = 0.02 * L, h = 0.4e-3;
  const Real r = t / 2;
  auto inside = [&](const Eigen::Vector3d& x) { return square || x[0] * x[0] + x[1] * x[1] <= r * r; };
  PointSet points = empty_point_set(h, 2);
  add_points(points, Eigen::Vector3d(-r, -r, 0), Eigen::Vector3d(r, r, L), "column", inside);
  for (auto& x : points.position) x[0] += a * std::sin(M_PI * x[2] / L);
  add_points(points, Eigen::Vector3d(-r, -r, -2 * h), Eigen::Vector3d(r, r, 0), "base", inside);
  add_points(points, Eigen::Vector3d(-r, -r, L), Eigen::Vector3d(r, r, L + 2 * h), "plate", inside);
  Settings s;
  s.cell_size = h;
  s.shape_function = shape;
  s.scheme = UpdateScheme::usl;
  s.cfl = 0.3;
  s.ddmp_stabilization = stabilization;
  s.threads = 2;
  Simulation sim(points,
                 {deformable("column", elastic(E, nu, rho)), rigid("base", BodyRole::fixed, Vec3::Zero(), rho),
                  rigid("plate", BodyRole::driven, Vec3(0, 0, -speed), rho)},
                 s);
  Real impulse = 0, span = 0;
  sim.add_observer([&](const Simulation&, const StepDiagnostics& d) {
    if (d.time * speed < from) return;
    impulse += -d.reaction[2][2] * d.dt;
    span += d.dt;
  });
  sim.run_until(travel / speed);
  return impulse / span;
}
}  // namespace

// DDMP against uGIMP on the buckled column with a round and with a square section of the same
// width (hidden: ~2 min of CPU; docs/solver.md, "DDMP column"): whether the stair-stepped
// round surface is where DDMP's post-buckling softness came from (it was not: the smoothed
// gradient's null space was). Plateau over the last quarter of 3 mm; DDMP at its default β.
TEST_CASE("Buckled column plateau, round against square section", "[.][column-section-study]") {
  for (bool square : {false, true})
    for (auto shape : {ShapeFunctionKind::ugimp, ShapeFunctionKind::ddmp})
      std::cout << "column " << (square ? "square" : "round") << " " << to_string(shape) << " plateau "
                << buckled_column_plateau(shape, Settings{}.ddmp_stabilization, square, 3e-3, 2.25e-3) << " N\n";
}

// DDMP's smoothed gradient has a null space (ddmp_stabilization.hpp): node-to-node zig-zags
// that no smoothed strain sees, so Paper A's DDMP as printed carries less than uGIMP once the
// column bends (docs/solver.md, "DDMP column: the cause, and the stabilization"). Issue 15's
// bound: the post-buckling load within 5 % of uGIMP's and 10 % of the Euler load. Paper A's
// column t = 1.6 mm, a = 0.02 L, at 0.4 mm cells (4 across), 100 mm/s, 2 mm of travel; load =
// the driven plate's mean reaction over 1.25–2 mm. The unstabilized run shows the softness
// the stabilization removes (measured: 0.94 of uGIMP; stabilized 0.98).
TEST_CASE("DDMP's buckled column carries uGIMP's load within 5 % once its null space is stabilized",
          "[mpm][buckling][ddmp]") {
  const Real t = 1.6e-3, L = 16e-3, E = 10e6, travel = 2e-3, from = 1.25e-3;
  const Real euler = M_PI * M_PI * E * (M_PI * std::pow(t, 4) / 64) / std::pow(0.5 * L, 2);  // 0.496 N
  const Real ugimp = buckled_column_plateau(ShapeFunctionKind::ugimp, 0, false, travel, from);
  const Real ddmp = buckled_column_plateau(ShapeFunctionKind::ddmp, Settings{}.ddmp_stabilization, false, travel, from);
  const Real printed = buckled_column_plateau(ShapeFunctionKind::ddmp, 0, false, travel, from);
  INFO("uGIMP " << ugimp << " N, DDMP " << ddmp << " N (" << ddmp / ugimp << " of uGIMP, " << ddmp / euler
                << " of Euler " << euler << " N), DDMP unstabilized " << printed << " N (" << printed / ugimp << ")");
  CHECK(std::abs(ddmp / ugimp - 1) < 0.05);
  CHECK(std::abs(ddmp / euler - 1) < 0.10);
  CHECK(printed / ugimp < 0.95);
}
