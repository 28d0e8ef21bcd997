// The J2 model in the solver's kernel form (j2_material.hpp): eight particles in one Pack
// give lane by lane what the scalar return gives, the history carries be, α and the plastic
// work, idle lanes stay zero and a failing lane turns NaN without touching the others.
#include <catch2/catch.hpp>

#include <random>

#include "mpm/j2_material.hpp"

using namespace latmpm::mpm;

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
  Pack history[J2Plastic::history_count];
  for (int k = 0; k < J2Plastic::history_count; ++k) history[k] = Pack{} + J2Plastic::history_initial[size_t(k)];
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
  Pack history[J2Plastic::history_count] = {};
  for (int q = 0; q < 5; ++q)  // lanes 5-7 idle (all-zero history, as the kernels leave them)
    for (int k = 0; k < J2Plastic::history_count; ++k) history[k][q] = J2Plastic::history_initial[size_t(k)];
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
