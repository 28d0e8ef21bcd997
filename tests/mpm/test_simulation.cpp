// Whole-step properties of Simulation: thread-count independence, the record-layer force,
// mass scaling and the time-step rule.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "mpm/observers.hpp"
#include "mpm/simulation.hpp"
#include "point_builders.hpp"

using namespace latmpm;
using namespace latmpm::mpm;
using namespace latmpm::mpm::test;

TEST_CASE("Results are identical for one and two threads", "[mpm][simulation]") {
  const auto shape = GENERATE(ShapeFunctionKind::ugimp, ShapeFunctionKind::bspline3, ShapeFunctionKind::ddmp);
  const Real h = 1e-3;
  PointSet points = empty_point_set(h, 2);
  add_points(points, Eigen::Vector3d(-9 * h, -3 * h, 0), Eigen::Vector3d(12 * h, 5 * h, 18 * h), "block");
  add_points(points, Eigen::Vector3d(-9 * h, -3 * h, 18 * h), Eigen::Vector3d(12 * h, 5 * h, 19 * h), "plate");
  std::mt19937 rng(2);
  std::uniform_real_distribution<Real> u(-0.2, 0.2);
  for (auto& x : points.position) x += h * Eigen::Vector3d(u(rng), u(rng), u(rng));
  auto run = [&](int threads) {
    Settings s;
    s.cell_size = h;
    s.shape_function = shape;
    s.scheme = scheme_for(shape);
    s.threads = threads;
    Simulation sim(points, {deformable("block", elastic(1e6, 0.3, 1000)),
                            rigid("plate", BodyRole::driven, Vec3(0.5, 0, -2), 1000)}, s);
    for (int n = 0; n < 25; ++n) sim.step();
    std::vector<Real> state;
    const Particles& ps = sim.particles();
    for (size_t p = 0; p < ps.size(); ++p) {
      state.push_back(ps.id[p]);
      for (int a = 0; a < 3; ++a) state.push_back(ps.position[p][a]), state.push_back(ps.velocity[p][a]);
      for (int c = 0; c < 6; ++c) state.push_back(ps.stress[p][c]);
    }
    const auto& d = sim.last_diagnostics();
    state.insert(state.end(), {d.reaction[1][0], d.reaction[1][2], d.kinetic_energy, d.strain_energy, d.external_work});
    return state;
  };
  const auto one = run(1), two = run(2);
  REQUIRE(one.size() == two.size());
  size_t differing = 0;
  for (size_t i = 0; i < one.size(); ++i) differing += one[i] != two[i];
  CHECK(differing == 0);
}

TEST_CASE("The record-layer force is the layer's mean vertical stress times its area", "[mpm][simulation]") {
  const Real h = 1e-3;
  PointSet points = empty_point_set(h, 2);
  add_points(points, Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(4 * h, 3 * h, 2 * h), "base");
  // The bottom layer of points (one point spacing, h/2, thick) is the record layer.
  tag_points(points, "record", [&](size_t p) { return points.position[p][2] < h / 2; });
  Settings s;
  s.cell_size = h;
  s.fixed_time_step = 1e-9;
  Simulation sim(points, {deformable("base", elastic(1e6, 0.3, 1000))}, s);
  CHECK(sim.record_area() == Approx(4 * h * 3 * h).epsilon(1e-12));
  const Real sigma_zz = -2e5;  // Pa, compression
  for (auto& stress : sim.mutable_particles().stress) stress[2] = sigma_zz;
  sim.step();
  // One tiny step changes the stress by a relative 1e-6 at most.
  CHECK(RecordLayerForce(sim)(sim) == Approx(sigma_zz * 12 * h * h).epsilon(1e-4));
}

TEST_CASE("Mass scaling multiplies the mass and enlarges the stable step by its square root", "[mpm][simulation]") {
  const Real h = 1e-3;
  PointSet points = empty_point_set(h, 2);
  add_points(points, Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(2 * h), "cube");
  const MaterialParameters m = elastic(10e6, 0.4, 1050);
  Settings s;
  s.cell_size = h;
  s.cfl = 0.4;
  Simulation plain(points, {deformable("cube", m)}, s);
  s.mass_scaling = 6;
  Simulation scaled(points, {deformable("cube", m)}, s);
  CHECK(scaled.particles().mass[0] == Approx(6 * 1050 * points.volume[0]));
  const Real c = std::sqrt(m.p_wave_modulus() / m.density);
  CHECK(plain.stable_time_step() == Approx(0.4 * h / c));
  CHECK(scaled.stable_time_step() == Approx(0.4 * h / c * std::sqrt(6.0)));
}
