// Material models against independent references: the Jaumann update against the matrix
// formula, stress-free rigid rotation, energy densities against their stresses.
#include <catch2/catch.hpp>

#include <Eigen/Dense>
#include <random>

#include "mpm/material_model.hpp"

using namespace latmpm::mpm;

namespace {
MaterialParameters params(MaterialKind kind) {
  MaterialParameters m;
  m.kind = kind;
  m.young_modulus = 10e6;
  m.poisson_ratio = 0.4;
  m.density = 1050;
  return m;
}

Mat3 random_matrix(std::mt19937& rng, Real scale) {
  std::uniform_real_distribution<Real> u(-scale, scale);
  Mat3 m;
  for (int i = 0; i < 9; ++i) m(i) = u(rng);
  return m;
}
}  // namespace

TEST_CASE("The linear elastic update is the Jaumann rate of Hooke's law", "[mpm][material]") {
  const auto le = LinearElastic::from(params(MaterialKind::linear_elastic), 1);
  std::mt19937 rng(3);
  for (int n = 0; n < 50; ++n) {
    const Mat3 L = random_matrix(rng, 50), sigma = [&] {
      const Mat3 a = random_matrix(rng, 1e5);
      return Mat3(a + a.transpose());
    }();
    const Real dt = 1e-5;
    const Mat3 D = 0.5 * (L + L.transpose()), W = 0.5 * (L - L.transpose());
    const Mat3 expected = sigma + dt * (le.lambda * D.trace() * Mat3::Identity() + 2 * le.mu * D + W * sigma - sigma * W);
    const SymTensor s = updated_stress(le, L, Mat3::Identity(), dt, to_voigt(sigma));
    CHECK((to_matrix(s) - expected).norm() <= 1e-12 * expected.norm());
  }
}

TEST_CASE("A rigid rotation leaves the stress magnitude unchanged", "[mpm][material]") {
  // Spin a uniaxially stressed body through 90° in small steps: the objective rate rotates
  // the stress with the body, σ_xx → σ_yy, and keeps its invariants.
  const auto le = LinearElastic::from(params(MaterialKind::linear_elastic), 1);
  const Real omega = 100, dt = 1e-6;  // rad/s, s
  Mat3 L = Mat3::Zero();
  L(0, 1) = -omega, L(1, 0) = omega;  // v = ω ẑ × x
  SymTensor s = SymTensor::Zero();
  s[0] = 1e5;
  const int steps = int(std::round(M_PI / 2 / omega / dt));
  for (int n = 0; n < steps; ++n) s = updated_stress(le, L, Mat3::Identity(), dt, s);
  CHECK(s[1] == Approx(1e5).epsilon(1e-3));
  CHECK(std::abs(s[0]) < 1e2);
  CHECK(to_matrix(s).norm() == Approx(1e5).epsilon(1e-3));
}

TEST_CASE("The neo-Hookean stress is the derivative of its energy", "[mpm][material]") {
  // σ = (1/J) ∂ψ/∂F Fᵀ, checked by central differences of strain_energy_density.
  const auto nh = NeoHookean::from(params(MaterialKind::neo_hookean), 1);
  std::mt19937 rng(9);
  for (int n = 0; n < 20; ++n) {
    const Mat3 F = Mat3::Identity() + random_matrix(rng, 0.3);
    const Real J = F.determinant();
    REQUIRE(J > 0);
    Mat3 P;  // first Piola–Kirchhoff stress by finite differences
    const Real eps = 1e-6;
    for (int i = 0; i < 9; ++i) {
      Mat3 Fp = F, Fm = F;
      Fp(i) += eps, Fm(i) -= eps;
      P(i) = (strain_energy_density(nh, Fp, SymTensor::Zero()) - strain_energy_density(nh, Fm, SymTensor::Zero())) / (2 * eps);
    }
    const Mat3 expected = P * F.transpose() / J;
    const SymTensor s = updated_stress(nh, Mat3::Zero(), F, 1e-6, SymTensor::Zero());
    CHECK((to_matrix(s) - expected).norm() <= 1e-6 * expected.norm());
  }
}

TEST_CASE("The linear elastic energy density is half stress times strain", "[mpm][material]") {
  const auto m = params(MaterialKind::linear_elastic);
  const auto le = LinearElastic::from(m, 1);
  // Uniaxial stress σ: ε = σ/E, w = σ²/(2E). Pure shear τ: w = τ²/(2G).
  SymTensor s = SymTensor::Zero();
  s[2] = 2e5;
  CHECK(strain_energy_density(le, Mat3::Identity(), s) == Approx(2e5 * 2e5 / (2 * m.young_modulus)));
  s.setZero();
  s[5] = 1e5;
  CHECK(strain_energy_density(le, Mat3::Identity(), s) == Approx(1e5 * 1e5 / (2 * m.shear_modulus())));
}

TEST_CASE("The linear elastic energy is the stress work, also at finite strain", "[mpm][material]") {
  // Uniaxial strain along z, stretch λ: D_zz = λ̇/λ, W = 0, so the rate form integrates to
  // σ_zz = M ln λ (M = λ_Lamé + 2μ), J = λ, and the stress work per reference volume is
  // ∫ J σ:D dt = ∫ M ln λ dλ = M (λ ln λ − λ + 1). The complementary energy ½ σ:C⁻¹σ J =
  // ½ M λ (ln λ)² agrees only for small strains. The steps follow the solver's update
  // F_new = (I + dt L) F_old, so the explicit scheme is within O(dt) of the exact path.
  const auto m = params(MaterialKind::linear_elastic);
  const auto le = LinearElastic::from(m, 1);
  const Real M = m.p_wave_modulus();
  const Real dt = 1e-5, speed = 40;  // |λ̇| = 40 /s: to λ = 0.6 in 1000 steps, then back
  SymTensor s = SymTensor::Zero();
  Real history[1] = {0};
  Mat3 F = Mat3::Identity();
  auto step = [&](Real stretch_rate) {
    Mat3 L = Mat3::Zero();
    L(2, 2) = stretch_rate / F(2, 2);
    F = (Mat3::Identity() + dt * L) * F;
    s = updated_stress(le, L, F, dt, s, history);
  };
  for (int n = 0; n < 1000; ++n) step(-speed);
  const Real stretch = F(2, 2);
  REQUIRE(stretch == Approx(0.6));
  const Real work = M * (stretch * std::log(stretch) - stretch + 1);
  const Real complementary = 0.5 * M * stretch * std::log(stretch) * std::log(stretch);
  CHECK(s[2] == Approx(M * std::log(stretch)).epsilon(1e-3));
  CHECK(strain_energy_density(le, F, s, history) == Approx(work).epsilon(1e-3));
  // The complementary energy of the computed stress is 16 % short of the work here.
  CHECK(strain_energy_density(le, F, s) == Approx(complementary).epsilon(1e-3));
  CHECK(strain_energy_density(le, F, s) < 0.85 * strain_energy_density(le, F, s, history));
  // Unloaded along the same path, the work comes back: the energy returns to zero.
  for (int n = 0; n < 1000; ++n) step(speed);
  REQUIRE(F(2, 2) == Approx(1));
  CHECK(std::abs(strain_energy_density(le, F, s, history)) < 1e-3 * work);
}

TEST_CASE("A rigid rotation of a stressed point does no work on it", "[mpm][material]") {
  // D = 0: the stress work is zero, so the energy stays what it was, at any angle.
  const auto le = LinearElastic::from(params(MaterialKind::linear_elastic), 1);
  std::mt19937 rng(11);
  SymTensor s;
  for (int c = 0; c < 6; ++c) s[c] = std::uniform_real_distribution<Real>(-2e5, 2e5)(rng);
  // The stress work of a point set up with this stress: its complementary energy.
  const Real before = strain_energy_density(le, Mat3::Identity(), s);
  Real history[1] = {before};
  Mat3 W = Mat3::Zero();
  W(0, 1) = 3, W(1, 0) = -3, W(1, 2) = 1, W(2, 1) = -1;
  const Real dt = 1e-4;
  Mat3 F = Mat3::Identity();
  for (int n = 0; n < 2000; ++n) {
    F = (Mat3::Identity() + dt * W) * F;
    s = updated_stress(le, W, F, dt, s, history);
  }
  CHECK(strain_energy_density(le, F, s, history) == Approx(before).epsilon(1e-12));
  // The explicit rotation update lets |σ| grow by O(dt²) a step: the complementary energy
  // drifts (so this test tells the two measures apart), the work does not.
  CHECK(std::abs(strain_energy_density(le, F, s) / before - 1) > 1e-5);
}

TEST_CASE("Wave speeds follow the P-wave modulus, mass scaling and compression", "[mpm][material]") {
  const auto m = params(MaterialKind::linear_elastic);
  const Real c2 = m.p_wave_modulus() / m.density;
  CHECK(LinearElastic::from(m, 1).wave_speed_squared(1) == Approx(c2));
  CHECK(LinearElastic::from(m, 6).wave_speed_squared(1) == Approx(c2 / 6));
  const auto nh = NeoHookean::from(params(MaterialKind::neo_hookean), 1);
  CHECK(nh.wave_speed_squared(1) == Approx(c2));
  CHECK(nh.wave_speed_squared(0.5) > c2);
}
