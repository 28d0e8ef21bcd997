#include "mpm/j2_plasticity.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/errors.hpp"

namespace latmpm::mpm {

Real J2Parameters::lame_lambda() const {
  return young_modulus * poisson_ratio / ((1 + poisson_ratio) * (1 - 2 * poisson_ratio));
}
Real J2Parameters::shear_modulus() const { return young_modulus / (2 * (1 + poisson_ratio)); }

Real J2Parameters::yield_stress(Real alpha) const {
  return saturation_yield + (initial_yield - saturation_yield) * std::exp(-saturation_rate * alpha) +
         linear_hardening * alpha;
}

Real J2Parameters::hardening_modulus(Real alpha) const {
  return -saturation_rate * (initial_yield - saturation_yield) * std::exp(-saturation_rate * alpha) +
         linear_hardening;
}

void J2Parameters::validate(const std::string& where) const {
  auto positive = [&](Real v, const char* field, const char* example) {
    if (!(v > 0) || !std::isfinite(v)) throw InputError(where, field, std::string("must be positive, e.g. ") + example);
  };
  auto non_negative = [&](Real v, const char* field, const char* example) {
    if (!(v >= 0) || !std::isfinite(v))
      throw InputError(where, field, std::string("must be zero or positive, e.g. ") + example);
  };
  positive(young_modulus, "young_modulus", "190GPa");
  if (!(poisson_ratio > -1 && poisson_ratio < 0.5)) throw InputError(where, "poisson_ratio", "must lie in (-1, 0.5)");
  positive(initial_yield, "initial_yield", "668MPa");
  positive(saturation_yield, "saturation_yield", "887MPa");
  non_negative(saturation_rate, "saturation_rate", "51.6");
  non_negative(linear_hardening, "linear_hardening", "285MPa");
}

// Johnson & Cook (1985) 4340 constants at 673 K and 2661.9 1/s, fitted to Eq. 10 over
// plastic strains 0–0.6; E at 400 °C. Sources and fit: docs/paper-b.md.
J2Parameters steel_42crmo4_400c() { return {190e9, 0.3, 667.8e6, 887.4e6, 51.6, 285.2e6}; }

// Lesuer (2000) Johnson–Cook constants at room temperature and 1 1/s, fitted to Eq. 10 over
// plastic strains 0–0.3. Sources and fit: docs/paper-b.md.
J2Parameters ti6al4v() { return {113.8e9, 0.342, 1098e6, 1119.3e6, 15.3, 1119.6e6}; }

namespace {

constexpr Real root_three_halves = 1.2247448713915890491;  // sqrt(3/2)

using Vec4 = Eigen::Matrix<Real, 4, 1>;
using Mat4 = Eigen::Matrix<Real, 4, 4>;

// Principal Kirchhoff stresses of Eq. 12 for logarithmic elastic stretches ε_i:
// τ_i = λ/2 (J² − 1) + μ (e^{2ε_i} − 1), J = e^{ε_1+ε_2+ε_3}.
Vec3 principal_kirchhoff(Real lambda, Real mu, const Vec3& log_stretch) {
  const Real j_squared = std::exp(2 * log_stretch.sum());
  Vec3 tau;
  for (int i = 0; i < 3; ++i) tau[i] = 0.5 * lambda * (j_squared - 1) + mu * (std::exp(2 * log_stretch[i]) - 1);
  return tau;
}

Vec3 deviator(const Vec3& v) { return v.array() - v.mean(); }

// Implicit exponential-map return (Eq. 13) in principal logarithmic stretches: unknowns
// ε_1..3 and Δγ, residuals ε − ε_trial + Δγ sqrt(3/2) n(ε) and φ(ε, α_n + Δγ) / μ. The
// trace of ε stays the trial one (tr n = 0), so J and the pressure are those of the trial.
struct Return {
  Vec3 log_stretch;
  Real delta_gamma;
  int iterations;
};

Return return_map(const J2Parameters& p, const Vec3& trial, Real alpha_n, Real trial_excess) {
  const Real lambda = p.lame_lambda(), mu = p.shear_modulus();
  // Start from a radial return with the stiffest shear modulus of the trial state, μ e^{2ε_max}
  // (Eq. 12 stiffens with stretch): the guess stays short of the return, on the trial's side
  // of the deviatoric origin, where the solution is (Δγ ≥ 0).
  const Vec3 s_trial = deviator(principal_kirchhoff(lambda, mu, trial));
  const Vec3 n_trial = s_trial / s_trial.norm();
  const Real slope = 3 * mu * std::exp(2 * trial.maxCoeff()) + std::max(p.hardening_modulus(alpha_n), Real(0));
  Real delta_gamma = trial_excess / slope;
  Vec3 eps = trial - delta_gamma * root_three_halves * n_trial;
  for (int it = 1; it <= 50; ++it) {
    const Vec3 e = (2 * eps).array().exp();
    const Vec3 s = mu * (e.array() - e.mean());
    const Real s_norm = s.norm();
    const Vec3 n = s / s_norm;
    const Real alpha = alpha_n + delta_gamma;
    Vec4 r;
    r.head<3>() = eps - trial + delta_gamma * root_three_halves * n;
    r[3] = (root_three_halves * s_norm - p.yield_stress(alpha)) / mu;
    Mat3 ds;  // ∂s_i/∂ε_j = 2μ e_j (δ_ij − 1/3)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) ds(i, j) = 2 * mu * e[j] * ((i == j) - Real(1) / 3);
    const Mat3 dn = (Mat3::Identity() - n * n.transpose()) / s_norm * ds;
    Mat4 jac;
    jac.topLeftCorner<3, 3>() = Mat3::Identity() + delta_gamma * root_three_halves * dn;
    jac.topRightCorner<3, 1>() = root_three_halves * n;
    jac.bottomLeftCorner<1, 3>() = root_three_halves * (n.transpose() * ds) / mu;
    jac(3, 3) = -p.hardening_modulus(alpha) / mu;
    Vec4 step = jac.partialPivLu().solve(-r);
    // Damped where a full step would cross the deviatoric origin or make Δγ negative: the
    // mirror image of the return (n flipped, Δγ < 0) also solves the residual equations.
    for (int halving = 0; halving < 30; ++halving) {
      const Vec3 next = eps + step.head<3>();
      if (delta_gamma + step[3] >= 0 && deviator(next).dot(n_trial) > 0) break;
      step *= 0.5;
    }
    eps += step.head<3>();
    delta_gamma += step[3];
    // Quadratic convergence: after a step of 1e-11 the error is far below rounding.
    if (step.cwiseAbs().maxCoeff() <= 1e-11 * (1 + delta_gamma) && r.cwiseAbs().maxCoeff() <= 1e-9)
      return {eps, delta_gamma, it};
  }
  std::ostringstream os;
  os << "J2 return mapping did not converge in 50 Newton iterations (trial log stretches " << trial.transpose()
     << ", alpha " << alpha_n << ")";
  throw NumericalError(os.str());
}

SymTensor spectral(const Mat3& vectors, const Vec3& values) {
  return to_voigt(vectors * values.asDiagonal() * vectors.transpose());
}

}  // namespace

J2Update j2_update(const J2Parameters& p, const Mat3& f, const J2State& previous) {
  if (!(f.determinant() > 0)) throw NumericalError("J2 update: the relative deformation gradient is not invertible (det f <= 0)");
  const Real lambda = p.lame_lambda(), mu = p.shear_modulus();
  // Elastic predictor: be_trial = f be_n fᵀ (Fp frozen), τ = λ/2 (J² − 1) I + μ (be − I) (Eq. 11–12).
  const Mat3 be_trial = f * to_matrix(previous.elastic_left_cauchy_green) * f.transpose();
  const Real j_squared = be_trial.determinant();
  const Mat3 dev_be = be_trial - be_trial.trace() / 3 * Mat3::Identity();
  const Real alpha_n = previous.plastic_arc_length;
  const Real excess = root_three_halves * mu * dev_be.norm() - p.yield_stress(alpha_n);  // φ, Eq. 9: dev τ = μ dev be

  J2Update out;
  out.state.plastic_arc_length = alpha_n;
  if (!(excess > 0)) {  // elastic: no eigen-decomposition needed
    const Mat3 tau = 0.5 * lambda * (j_squared - 1) * Mat3::Identity() + mu * (be_trial - Mat3::Identity());
    out.state.elastic_left_cauchy_green = to_voigt(be_trial);
    out.kirchhoff = to_voigt(tau);
    out.cauchy = out.kirchhoff / std::sqrt(j_squared);
    return out;
  }
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(be_trial);
  const Vec3 trial = 0.5 * eig.eigenvalues().array().log();  // ε_i = ln λe_i
  const Return r = return_map(p, trial, alpha_n, excess);
  out.plastic_increment = r.delta_gamma;
  out.newton_iterations = r.iterations;
  out.state.plastic_arc_length = alpha_n + r.delta_gamma;
  out.state.elastic_left_cauchy_green = spectral(eig.eigenvectors(), (2 * r.log_stretch).array().exp());
  out.kirchhoff = spectral(eig.eigenvectors(), principal_kirchhoff(lambda, mu, r.log_stretch));
  out.cauchy = out.kirchhoff / std::exp(r.log_stretch.sum());
  out.dissipation = r.delta_gamma * p.yield_stress(out.state.plastic_arc_length);
  return out;
}

Real j2_stored_energy(const J2Parameters& p, const J2State& state) {
  const Mat3 be = to_matrix(state.elastic_left_cauchy_green);
  const Real j_squared = be.determinant();
  const Real log_j_squared = std::log(j_squared);
  return 0.25 * p.lame_lambda() * (j_squared - 1 - log_j_squared) +
         0.5 * p.shear_modulus() * (be.trace() - 3 - log_j_squared);
}

}  // namespace latmpm::mpm
