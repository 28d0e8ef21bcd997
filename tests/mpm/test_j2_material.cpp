// The J2 model in the solver's kernel form (j2_material.hpp): eight particles in one Pack
// give lane by lane what the scalar return gives, the history carries be, α and the plastic
// work, idle lanes stay zero and a failing lane turns NaN without touching the others; in
// the solver, a J2 body under a homogeneous deformation follows the one-point return.
#include <catch2/catch.hpp>

#include <random>

#include "mpm/j2_material.hpp"
#include "mpm/simulation.hpp"
#include "mpm/simulation_test_access.hpp"
#include "point_builders.hpp"

using namespace latmpm;
using namespace latmpm::mpm;
using namespace latmpm::mpm::test;

namespace {

J2Plastic steel() { return {steel_42crmo4_400c(), 7850}; }

Deformation<Pack> pack_deformation(const std::array<Mat3, pack_width>& L, Real dt) {
  Deformation<Pack> d;
  d.dt = dt;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      for (int q = 0; q < pack_width; ++q) d.velocity_gradient[a][b][q] = L[size_t(q)](a, b);
  return d;
}

}  // namespace

TEST_CASE("A Pack of eight J2 particles updates lane by lane like the scalar return", "[mpm][j2]") {
  const J2Plastic model = steel();
  std::mt19937 rng(21);
  std::uniform_real_distribution<Real> u(-1, 1);
  std::array<Mat3, pack_width> L;
  std::array<J2State, pack_width> scalar;
  Pack history[J2Plastic::history.size()];
  for (size_t k = 0; k < J2Plastic::history.size(); ++k) history[k] = Pack{} + J2Plastic::history[k].initial;
  Real plastic_work[pack_width] = {};
  const Real dt = 1e-6;
  for (int q = 0; q < pack_width; ++q)
    for (int i = 0; i < 9; ++i) L[size_t(q)](i) = 2000 * u(rng);  // strain rates ~1e3 1/s
  Pack s[6] = {};
  for (int step = 0; step < 200; ++step) {  // ~0.2 strain: every lane yields
    model.update_stress(pack_deformation(L, dt), s, history);
    for (int q = 0; q < pack_width; ++q) {
      const J2Update ref = j2_update(model.parameters, Mat3::Identity() + dt * L[size_t(q)], scalar[size_t(q)]);
      scalar[size_t(q)] = ref.state;
      plastic_work[q] += ref.dissipation;
      for (int c = 0; c < 6; ++c) REQUIRE(s[c][q] == ref.cauchy[c]);
    }
  }
  Deformation<Pack> any;
  const Pack energy = model.strain_energy_density(any, s, history);
  for (int q = 0; q < pack_width; ++q) {
    CHECK(history[6][q] == scalar[size_t(q)].plastic_arc_length);
    CHECK(history[6][q] > 0.01);
    CHECK(history[7][q] == Approx(plastic_work[q]).epsilon(1e-14));
    CHECK(energy[q] == j2_stored_energy(model.parameters, scalar[size_t(q)]));
  }
}

TEST_CASE("Idle J2 lanes stay zero and a failing lane turns NaN alone", "[mpm][j2]") {
  const J2Plastic model = steel();
  std::array<Mat3, pack_width> L;
  L.fill(Mat3::Zero());
  L[3] = -2e6 * Mat3::Identity();  // det(I + dt L) < 0 at dt = 1e-6: an inverted step
  Pack history[J2Plastic::history.size()] = {};
  for (int q = 0; q < 5; ++q)  // lanes 5-7 idle (all-zero history, as the kernels leave them)
    for (size_t k = 0; k < J2Plastic::history.size(); ++k) history[k][q] = J2Plastic::history[k].initial;
  Pack s[6] = {};
  model.update_stress(pack_deformation(L, 1e-6), s, history);
  Deformation<Pack> any;
  const Pack energy = model.strain_energy_density(any, s, history);
  for (int q = 0; q < pack_width; ++q) {
    if (q == 3) {
      CHECK(std::isnan(s[0][q]));
      continue;
    }
    for (int c = 0; c < 6; ++c) CHECK(s[c][q] == 0);
    CHECK(energy[q] == 0);
  }
  CHECK(model.wave_speed_squared(1) == Approx((model.parameters.lame_lambda() + 2 * model.parameters.shear_modulus()) / 7850));
}

TEST_CASE("A J2 body in the solver follows the one-point return under a homogeneous deformation", "[mpm][j2]") {
  // Every grid node gets v = A x, so every particle sees L = A exactly (test_transfers.cpp):
  // its stress and history after 100 steps (strain ~0.5) are those of j2_update applied to
  // f = I + Δt A 100 times, and its plastic arc length sits in the history column.
  const Real h = 1e-3, dt = 1e-5;
  PointSet points = empty_point_set(h, 2);
  add_points(points, Eigen::Vector3d::Zero(), Eigen::Vector3d(2e-3, 2e-3, 2e-3), "block");
  const J2Parameters j2 = steel_42crmo4_400c();
  MaterialParameters m = elastic(j2.young_modulus, j2.poisson_ratio, 7850, MaterialKind::j2);
  m.initial_yield = j2.initial_yield, m.saturation_yield = j2.saturation_yield;
  m.saturation_rate = j2.saturation_rate, m.linear_hardening = j2.linear_hardening;
  Settings settings;
  settings.cell_size = h;
  Simulation sim(points, {deformable("block", m)}, settings);
  Mat3 A;
  A << -500, 300, 0, 0, 250, 0, 0, 0, 250;  // 1/s: compression along x with shear
  J2State state;
  J2Update ref;
  for (int k = 0; k < 100; ++k) {
    SimulationTestAccess::particles_to_grid(sim);
    SimulationTestAccess::set_grid_velocity(sim, [&](const Vec3& x) { return Vec3(A * x); });
    SimulationTestAccess::grid_to_particles(sim, dt);
    ref = j2_update(j2, Mat3::Identity() + dt * A, state);
    state = ref.state;
  }
  REQUIRE(state.plastic_arc_length > 0.3);
  const Particles& ps = sim.particles();
  const HistoryColumn* alpha = ps.history_column("j2_alpha");
  const HistoryColumn* work = ps.history_column("j2_plastic_work");
  REQUIRE(alpha != nullptr);
  REQUIRE(work != nullptr);
  for (size_t p = 0; p < ps.size(); ++p) {
    CHECK((ps.stress[p] - ref.cauchy).norm() <= 1e-9 * ref.cauchy.norm());
    CHECK(alpha->values[p] == Approx(state.plastic_arc_length).epsilon(1e-10));
    CHECK(work->values[p] > j2.initial_yield * state.plastic_arc_length);
  }
}
