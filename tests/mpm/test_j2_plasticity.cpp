// Finite-strain J2 plasticity (paper B Eq. 9–13) at one material point against references
// that share no code with the return mapping: a closed-form uniaxial-stress path (the
// elastic stretches of Eq. 12 from a scalar bisection, the plastic stretch e^α), and for
// simple shear, where the principal axes turn, a finely stepped RK4 integration of the
// continuum rate form ḃe = l be + be lᵀ − 2 γ̇ sqrt(3/2) n be with the consistency condition.
#include <catch2/catch.hpp>

#include <Eigen/Dense>
#include <cmath>
#include <functional>
#include <random>

#include "mpm/j2_plasticity.hpp"

using namespace latmpm::mpm;

namespace {

const Real c = std::sqrt(1.5);

Mat3 diagonal(Real a, Real b) { return Vec3(a, b, b).asDiagonal(); }

// Uniaxial Kirchhoff stress τ along x with free lateral faces: the elastic stretches of
// Eq. 12 (τ_yy = λ/2 (J²−1) + μ(λ2² − 1) = 0, τ_xx − τ_yy = μ(λ1² − λ2²)) by bisection on λ2².
struct ElasticStretches {
  Real axial, lateral;
};
ElasticStretches uniaxial_elastic(const J2Parameters& p, Real tau) {
  const Real lam = p.lame_lambda(), mu = p.shear_modulus();
  auto lateral_stress = [&](Real x) {  // x = λ2²; τ_yy, increasing in x
    const Real axial_sq = x + tau / mu;
    return 0.5 * lam * (axial_sq * x * x - 1) + mu * (x - 1);
  };
  Real lo = 1e-3, hi = 2;
  for (int i = 0; i < 200; ++i) {
    const Real mid = 0.5 * (lo + hi);
    (lateral_stress(mid) > 0 ? hi : lo) = mid;
  }
  const Real x = 0.5 * (lo + hi);
  return {std::sqrt(x + tau / mu), std::sqrt(x)};
}

// Total F on the uniaxial path for the axial stress τ and the plastic arc length α
// (isochoric plastic stretch e^α along x, e^(−α/2) across).
Mat3 uniaxial_f(const J2Parameters& p, Real tau, Real alpha) {
  const ElasticStretches e = uniaxial_elastic(p, tau);
  return diagonal(e.axial * std::exp(alpha), e.lateral * std::exp(-alpha / 2));
}

Real relative(const SymTensor& a, const SymTensor& b) { return (a - b).norm() / b.norm(); }

SymTensor kirchhoff_of(const J2Parameters& p, const Mat3& be) {
  const Mat3 tau = 0.5 * p.lame_lambda() * (be.determinant() - 1) * Mat3::Identity() +
                   p.shear_modulus() * (be - Mat3::Identity());
  return to_voigt(tau);
}

// Simple shear F = I + γ e_x⊗e_y, reference by RK4 in γ with the yield point located exactly.
struct ShearReference {
  Mat3 be;
  Real alpha;
};
ShearReference shear_reference(const J2Parameters& p, Real gamma_end, int steps) {
  const Real mu = p.shear_modulus();
  auto shear = [](Real g) { Mat3 F = Mat3::Identity(); F(0, 1) = g; return F; };
  auto excess_elastic = [&](Real g) {
    const Mat3 b = shear(g) * shear(g).transpose();
    const Mat3 dev = b - b.trace() / 3 * Mat3::Identity();
    return c * mu * dev.norm() - p.yield_stress(0);
  };
  if (excess_elastic(gamma_end) <= 0) return {shear(gamma_end) * shear(gamma_end).transpose(), 0};
  Real lo = 0, hi = gamma_end;
  for (int i = 0; i < 200; ++i) {
    const Real mid = 0.5 * (lo + hi);
    (excess_elastic(mid) > 0 ? hi : lo) = mid;
  }
  const Real gamma_yield = 0.5 * (lo + hi);
  Mat3 l = Mat3::Zero();
  l(0, 1) = 1;  // dγ/dγ: velocity gradient per unit shear
  using State = Eigen::Matrix<Real, 10, 1>;
  auto rate = [&](const State& y) {
    const Mat3 be = Eigen::Map<const Mat3>(y.data());
    const Mat3 dev = be - be.trace() / 3 * Mat3::Identity();
    const Mat3 n = dev / dev.norm();
    Mat3 bdot = l * be + be * l.transpose();
    const Real gamma_dot = c * mu * (n.cwiseProduct(bdot)).sum() /
                           (p.hardening_modulus(y[9]) + 3 * mu * (n.cwiseProduct(n * be)).sum());
    bdot -= 2 * c * gamma_dot * 0.5 * (n * be + be * n);
    State d;
    Eigen::Map<Mat3>(d.data()) = bdot;
    d[9] = gamma_dot;
    return d;
  };
  State y;
  Eigen::Map<Mat3>(y.data()) = shear(gamma_yield) * shear(gamma_yield).transpose();
  y[9] = 0;
  const Real h = (gamma_end - gamma_yield) / steps;
  for (int i = 0; i < steps; ++i) {
    const State k1 = rate(y), k2 = rate(y + h / 2 * k1), k3 = rate(y + h / 2 * k2), k4 = rate(y + h * k3);
    y += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return {Eigen::Map<const Mat3>(y.data()), y[9]};
}

// Drive the model through a sequence of total deformation gradients.
J2Update drive(const J2Parameters& p, const std::vector<Mat3>& path, J2State& state) {
  J2Update last;
  for (size_t k = 1; k < path.size(); ++k) {
    last = j2_update(p, path[k] * path[k - 1].inverse(), state);
    state = last.state;
  }
  return last;
}

J2Parameters perfectly_plastic() {
  J2Parameters p = steel_42crmo4_400c();
  p.saturation_yield = p.initial_yield;
  p.linear_hardening = 0;
  return p;
}

}  // namespace

TEST_CASE("Uniaxial tension follows the closed-form finite-strain path, elastic and plastic", "[mpm][j2]") {
  const J2Parameters p = GENERATE(steel_42crmo4_400c(), ti6al4v());
  J2State state;
  Mat3 previous = Mat3::Identity();
  // Elastic up to 0.9 y0, then plastic in arc-length increments of 0.01 up to α = 0.5.
  std::vector<std::pair<Real, Real>> targets;  // (τ_xx, α)
  for (int k = 1; k <= 9; ++k) targets.push_back({0.1 * k * p.initial_yield, 0});
  for (int k = 1; k <= 50; ++k) targets.push_back({p.yield_stress(0.01 * k), 0.01 * k});
  for (const auto& [tau, alpha] : targets) {
    const Mat3 F = uniaxial_f(p, tau, alpha);
    const J2Update u = j2_update(p, F * previous.inverse(), state);
    state = u.state;
    previous = F;
    SymTensor expected = SymTensor::Zero();
    expected[0] = tau;
    CHECK((u.kirchhoff - expected).norm() <= 1e-9 * tau);
    CHECK(std::abs(state.plastic_arc_length - alpha) <= 1e-9 * std::max(alpha, Real(1e-3)));
    CHECK(relative(u.cauchy, u.kirchhoff / F.determinant()) <= 1e-12);
  }
}

TEST_CASE("Without hardening the uniaxial stress plateaus at the initial yield stress", "[mpm][j2]") {
  const J2Parameters p = perfectly_plastic();
  J2State state;
  std::vector<Mat3> path{Mat3::Identity()};
  // Axial log strain to 1.0 in 100 steps, lateral stretches from the plateau's elastic state.
  const ElasticStretches plateau = uniaxial_elastic(p, p.initial_yield);
  for (int k = 1; k <= 100; ++k) {
    const Real alpha = 0.01 * k - std::log(plateau.axial);
    if (alpha <= 0) continue;
    path.push_back(uniaxial_f(p, p.initial_yield, alpha));
    const J2Update u = drive(p, {path[path.size() - 2], path.back()}, state);
    const Real von_mises_kirchhoff = von_mises(u.kirchhoff);
    CHECK(std::abs(von_mises_kirchhoff - p.initial_yield) <= 1e-10 * p.initial_yield);
    CHECK(std::abs(u.kirchhoff[0] - p.initial_yield) <= 1e-9 * p.initial_yield);
  }
  CHECK(state.plastic_arc_length > 0.99);
}

TEST_CASE("Unloading is elastic with Young's modulus and leaves the plastic stretch e^alpha", "[mpm][j2]") {
  const J2Parameters p = steel_42crmo4_400c();
  const Real alpha = 0.2;
  J2State state;
  drive(p, {Mat3::Identity(), uniaxial_f(p, p.yield_stress(alpha), alpha)}, state);
  REQUIRE(std::abs(state.plastic_arc_length - alpha) <= 1e-9);
  Mat3 previous = uniaxial_f(p, p.yield_stress(alpha), alpha);
  const Real small = 1e-4 * p.initial_yield;
  Real tau_before_last = 0, strain_before_last = 0;
  for (Real tau : {0.5 * p.yield_stress(alpha), small, Real(0)}) {
    const Mat3 F = uniaxial_f(p, tau, alpha);
    const J2Update u = j2_update(p, F * previous.inverse(), state);
    CHECK(u.plastic_increment == 0);
    CHECK(std::abs(u.kirchhoff[0] - tau) <= 1e-9 * p.initial_yield);
    if (tau == 0) {
      // Residual stretch: the plastic stretch alone (no elastic recovery left).
      CHECK(std::abs(std::log(F(0, 0)) - alpha) <= 1e-12);
      // Slope of the last increment, from the model's own stresses: E in the small-strain limit.
      const Real slope = (tau_before_last - u.kirchhoff[0]) / (strain_before_last - std::log(F(0, 0)));
      CHECK(std::abs(slope / p.young_modulus - 1) <= 1e-4);
    }
    tau_before_last = u.kirchhoff[0];
    strain_before_last = std::log(F(0, 0));
    state = u.state;
    previous = F;
  }
  CHECK(state.plastic_arc_length == Approx(alpha).epsilon(1e-12));
}

TEST_CASE("Simple shear matches a finely stepped integration of the rate form", "[mpm][j2]") {
  const J2Parameters p = GENERATE(steel_42crmo4_400c(), ti6al4v(), perfectly_plastic());
  const Real gamma_end = 0.5;
  const ShearReference ref = shear_reference(p, gamma_end, 4000);
  const ShearReference ref_half = shear_reference(p, gamma_end, 2000);
  INFO("RK4 self-convergence " << relative(kirchhoff_of(p, ref.be), kirchhoff_of(p, ref_half.be)));
  REQUIRE(relative(kirchhoff_of(p, ref.be), kirchhoff_of(p, ref_half.be)) <= 1e-10);  // RK4 converged far below 1e-6
  REQUIRE(ref.alpha > 0.1);
  // The implicit exponential map is first order where the principal axes turn: 5e5 steps.
  const int steps = 500000;
  J2State state;
  Mat3 f = Mat3::Identity();
  f(0, 1) = gamma_end / steps;
  J2Update u;
  for (int k = 0; k < steps; ++k) u = j2_update(p, f, state), state = u.state;
  INFO("relative stress error " << relative(u.kirchhoff, kirchhoff_of(p, ref.be)) << ", alpha " << state.plastic_arc_length
                                 << " against " << ref.alpha);
  CHECK(relative(u.kirchhoff, kirchhoff_of(p, ref.be)) <= 1e-6);
  CHECK(std::abs(state.plastic_arc_length / ref.alpha - 1) <= 1e-6);
}

TEST_CASE("A superposed rigid rotation rotates the stress and leaves the history's invariants", "[mpm][j2]") {
  const J2Parameters p = steel_42crmo4_400c();
  const Vec3 axis = Vec3(1, 2, 3).normalized();
  const int steps = 400;
  std::vector<Mat3> F(steps + 1), Q(steps + 1);
  for (int k = 0; k <= steps; ++k) {
    const Real t = Real(k) / steps;
    F[k] = Mat3::Identity();
    F[k](0, 1) = 0.4 * t;  // shear with stretch: non-proportional, plastic
    F[k](0, 0) = 1 + 0.1 * t;
    Q[k] = Eigen::AngleAxis<Real>(M_PI / 2 * t, axis).toRotationMatrix();
  }
  J2State plain, rotated;
  for (int k = 1; k <= steps; ++k) {
    const J2Update a = j2_update(p, F[k] * F[k - 1].inverse(), plain);
    const J2Update b = j2_update(p, Q[k] * F[k] * (Q[k - 1] * F[k - 1]).inverse(), rotated);
    plain = a.state, rotated = b.state;
    const Mat3 expected = Q[k] * to_matrix(a.kirchhoff) * Q[k].transpose();
    CHECK((to_matrix(b.kirchhoff) - expected).norm() <= 1e-9 * to_matrix(a.kirchhoff).norm());
    CHECK(std::abs(rotated.plastic_arc_length - plain.plastic_arc_length) <= 1e-12);
  }
  CHECK(plain.plastic_arc_length > 0.1);
}

TEST_CASE("Plastic flow is isochoric: det Fp = det F / sqrt(det be) stays 1", "[mpm][j2]") {
  const J2Parameters p = ti6al4v();
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> u(-0.01, 0.01);
  J2State state;
  Mat3 F = Mat3::Identity();
  Real dissipated = 0;
  for (int k = 0; k < 2000; ++k) {
    // Random isochoric increments with a small volume change and a drift that keeps the
    // point yielding.
    Mat3 f = Mat3::Identity();
    for (int i = 0; i < 9; ++i) f(i) += u(rng);
    f(0, 0) += 0.004;
    f(1, 2) += 0.003;
    f *= (1 + 0.05 * u(rng)) / std::cbrt(f.determinant());
    const J2Update step = j2_update(p, f, state);
    REQUIRE(step.plastic_increment >= 0);
    REQUIRE(step.newton_iterations <= 8);
    dissipated += step.dissipation;
    state = step.state;
    F = f * F;
    const Real det_fp = F.determinant() / std::sqrt(to_matrix(state.elastic_left_cauchy_green).determinant());
    REQUIRE(std::abs(det_fp - 1) <= 1e-12);
  }
  CHECK(state.plastic_arc_length > 1);
  CHECK(dissipated > p.initial_yield * state.plastic_arc_length);  // y(α) ≥ y0 for these sets
}

TEST_CASE("The work done equals the stored energy plus the plastic dissipation", "[mpm][j2]") {
  // Simple shear to γ = 0.5 in 1e5 steps. Stress power per reference volume τ : d (trapezoid
  // over each step) against ψ(be) of Eq. 12 plus Σ Δγ y(α): the balance the SHPB's energy
  // check rests on.
  const J2Parameters p = GENERATE(steel_42crmo4_400c(), ti6al4v());
  const int steps = 100000;
  const Real dgamma = 0.5 / steps;
  Mat3 f = Mat3::Identity();
  f(0, 1) = dgamma;
  J2State state;
  Real work = 0, dissipated = 0, tau_xy = 0;
  for (int k = 0; k < steps; ++k) {
    const J2Update u = j2_update(p, f, state);
    // d Δt = sym(f − I) to first order; its xy and yx parts each carry dγ/2.
    work += 0.5 * (tau_xy + u.kirchhoff[5]) * dgamma;
    tau_xy = u.kirchhoff[5];
    dissipated += u.dissipation;
    state = u.state;
  }
  const Real stored = j2_stored_energy(p, state);
  INFO("work " << work << " J/m^3, stored " << stored << ", dissipated " << dissipated << ", relative imbalance "
                << (work - stored - dissipated) / work);
  CHECK(dissipated > 10 * stored);
  CHECK(std::abs(work - stored - dissipated) <= 1e-4 * work);
}

TEST_CASE("J2 parameters are checked", "[mpm][j2]") {
  J2Parameters p = steel_42crmo4_400c();
  CHECK_NOTHROW(p.validate("scene.toml"));
  p.poisson_ratio = 0.5;
  CHECK_THROWS_WITH(p.validate("scene.toml"), Catch::Contains("poisson_ratio"));
  p = steel_42crmo4_400c();
  p.initial_yield = -1;
  CHECK_THROWS_WITH(p.validate("scene.toml"), Catch::Contains("initial_yield"));
}
