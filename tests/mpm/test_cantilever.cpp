// A cantilever under its own weight against beam theory: the static tip deflection
// w(x) = q/(24 E I) (x⁴ − 4 L x³ + 6 L² x²) + q (L x − x²/2)/(κ G A) (Euler–Bernoulli plus
// Timoshenko's shear term, κ = 5/6, G = E/2 at ν = 0), q = ρ g A. ν = 0, so the slab's width
// (one cell) does not enter. The load is applied at once and the beam left to vibrate
// (FLIP 0.99, almost undamped): the static deflection is the tip displacement averaged over
// whole periods of the vibration (between zero crossings of the tip's velocity averaged
// over a period), which removes the first mode exactly and the higher ones to O(1/(ω_k T)).
//
// Measured (docs/solver.md, "DDMP in bending", `test_mpm "[cantilever-study]"`): the
// cell-size convergence of uGIMP and DDMP; the test holds the bound, DDMP's error at
// 4 cells across at most twice uGIMP's.
#include <catch2/catch.hpp>

#include <cmath>
#include <iostream>
#include <vector>

#include "mpm/simulation.hpp"
#include "point_builders.hpp"

using namespace latmpm;
using namespace latmpm::mpm;
using namespace latmpm::mpm::test;

namespace {
constexpr Real young = 1e6, density = 1000, thickness = 4e-3, slenderness = 8;  // Pa, kg/m³, m

struct TipDeflection {
  Real measured = 0, reference = 0;
  Real error() const { return measured / reference - 1; }
};

// The cantilever `across` cells thick, clamped by a fixed block at x < 0, under gravity g in −z;
// one cell wide (a slab), or as wide as thick (`square`: a square section, free on four sides).
TipDeflection cantilever(ShapeFunctionKind shape, int across, bool ddmp_subpoints = false, bool square = false) {
  const Real h = thickness / across, length = slenderness * thickness, g = 3e-4;
  const Real width = square ? thickness : h;
  PointSet points = empty_point_set(h, 2);
  add_points(points, Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(length, width, thickness), "beam");
  add_points(points, Eigen::Vector3d(-2 * h, 0, 0), Eigen::Vector3d(0, width, thickness), "clamp");
  Settings s;
  s.cell_size = h;
  s.shape_function = shape;
  s.scheme = UpdateScheme::usl;
  s.ddmp_subpoints = ddmp_subpoints;
  if (ddmp_subpoints) s.ddmp_stabilization = 0;  // the sub-points study is unstabilized
  s.threads = 2;
  s.gravity = Vec3(0, 0, -g);
  Simulation sim(points,
                 std::vector<BodySettings>{deformable("beam", elastic(young, 0, density)),
                                           rigid("clamp", BodyRole::fixed, Vec3::Zero(), density)},
                 s);
  // Tip: the points of the last cell; beam theory at their mean x.
  std::vector<size_t> tip;
  Real tip_x = 0;
  for (size_t p = 0; p < sim.particles().size(); ++p)
    if (sim.particles().body[p] == 0 && sim.particles().position[p][0] > length - h) {
      tip.push_back(p);
      tip_x += sim.particles().position[p][0];
    }
  tip_x /= Real(tip.size());
  Real z0 = 0;
  for (size_t p : tip) z0 += sim.particles().position[p][2];
  z0 /= Real(tip.size());
  // Average over whole periods: the tip's mean displacement u(t) and velocity; a period ends
  // where the velocity crosses zero from below the second time after the start (the first
  // crossing from below is at one period for an oscillation that starts at rest).
  const Real r2 = thickness * thickness / 12;
  const Real omega = 1.8751 * 1.8751 / (length * length) * std::sqrt(young * r2 / density);
  const Real period = 2 * M_PI / omega;
  Real integral = 0, previous_u = 0, previous_v = 0, end = 0;
  int upward_crossings = 0;
  while (sim.time() < 4 * period) {
    const Real t0 = sim.time();
    sim.step();
    Real u = 0, v = 0;
    for (size_t p : tip) u += sim.particles().position[p][2], v += sim.particles().velocity[p][2];
    u = u / Real(tip.size()) - z0;
    v /= Real(tip.size());
    integral += Real(0.5) * (u + previous_u) * (sim.time() - t0);
    if (previous_v < 0 && v >= 0 && ++upward_crossings == 2) {
      end = sim.time();
      break;
    }
    previous_u = u, previous_v = v;
  }
  REQUIRE(end > 0);
  const Real q = density * g * thickness * width;  // per unit length
  const Real I = width * thickness * thickness * thickness / 12, A = width * thickness;
  const Real x = tip_x;
  const Real bending = q / (24 * young * I) * (x * x * x * x - 4 * length * x * x * x + 6 * length * length * x * x);
  const Real shear = q * (length * x - x * x / 2) / (Real(5) / 6 * young / 2 * A);
  return {-integral / end, bending + shear};
}
}  // namespace

TEST_CASE("DDMP's cantilever deflects within twice uGIMP's error of beam theory at 4 cells across",
          "[mpm][ddmp][cantilever]") {
  const TipDeflection ugimp = cantilever(ShapeFunctionKind::ugimp, 4);
  const TipDeflection ddmp = cantilever(ShapeFunctionKind::ddmp, 4);
  // The study option grid.ddmp_subpoints (shape_ddmp_subpoints.hpp) holds the same bound.
  const TipDeflection subpoints = cantilever(ShapeFunctionKind::ddmp, 4, true);
  INFO("tip deflection / beam theory: uGIMP " << 1 + ugimp.error() << ", DDMP " << 1 + ddmp.error()
                                              << ", DDMP with sub-points " << 1 + subpoints.error());
  CHECK(std::abs(ugimp.error()) < 0.1);
  CHECK(std::abs(ddmp.error()) <= 2 * std::abs(ugimp.error()));
  CHECK(std::abs(subpoints.error()) <= 2 * std::abs(ugimp.error()));
}

// The convergence table and plot of docs/solver.md (hidden: about a minute of CPU;
// bench/mpm/cantilever_study.sh runs it and plots it).
TEST_CASE("Cantilever tip deflection against cell size", "[.][cantilever-study]") {
  for (int across : {2, 4, 8})
    for (auto shape : {ShapeFunctionKind::ugimp, ShapeFunctionKind::ddmp, ShapeFunctionKind::linear}) {
      const TipDeflection d = cantilever(shape, across);
      std::cout << "cantilever " << to_string(shape) << " across " << across << " measured " << d.measured
                << " m reference " << d.reference << " m ratio " << 1 + d.error() << "\n";
    }
}

// The same with a square section, 4 cells each way (hidden; docs/solver.md, "DDMP column"):
// a slab one cell wide has no free side faces in y to smooth over.
TEST_CASE("Square cantilever tip deflection", "[.][cantilever-square]") {
  for (auto shape : {ShapeFunctionKind::ugimp, ShapeFunctionKind::ddmp}) {
    const TipDeflection d = cantilever(shape, 4, false, true);
    std::cout << "square cantilever " << to_string(shape) << " across 4 measured " << d.measured << " m reference "
              << d.reference << " m ratio " << 1 + d.error() << "\n";
  }
}
