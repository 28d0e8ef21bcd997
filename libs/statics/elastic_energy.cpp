#include "statics/elastic_energy.hpp"

#include <cmath>

#include <Eigen/LU>

namespace latmpm::statics {

ElasticEnergy ElasticEnergy::from(const mpm::MaterialParameters& m) {
  return {m.kind, m.lame_lambda(), m.shear_modulus()};
}

Real ElasticEnergy::density(const Mat3& F) const {
  if (kind == mpm::MaterialKind::linear_elastic) {
    const Mat3 eps = Real(0.5) * (F + F.transpose()) - Mat3::Identity();
    const Real tr = eps.trace();
    return mu * eps.squaredNorm() + Real(0.5) * lambda * tr * tr;
  }
  const Real log_j = std::log(F.determinant());
  return Real(0.5) * mu * (F.squaredNorm() - 3) - mu * log_j + Real(0.5) * lambda * log_j * log_j;
}

Mat3 ElasticEnergy::first_piola(const Mat3& F) const {
  if (kind == mpm::MaterialKind::linear_elastic) {
    const Mat3 eps = Real(0.5) * (F + F.transpose()) - Mat3::Identity();
    return 2 * mu * eps + lambda * eps.trace() * Mat3::Identity();
  }
  // P = μ (F − F⁻ᵀ) + λ ln J F⁻ᵀ
  const Mat3 f_inv_t = F.inverse().transpose();
  return mu * (F - f_inv_t) + lambda * std::log(F.determinant()) * f_inv_t;
}

Mat9 ElasticEnergy::tangent(const Mat3& F) const {
  Mat9 A = Mat9::Zero();
  if (kind == mpm::MaterialKind::linear_elastic) {
    // ∂P_ab/∂F_cd = μ (δac δbd + δad δbc) + λ δab δcd
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        A(3 * a + b, 3 * a + b) += mu;
        A(3 * a + b, 3 * b + a) += mu;
        if (a == b)
          for (int c = 0; c < 3; ++c) A(3 * a + a, 3 * c + c) += lambda;
      }
    return A;
  }
  // ∂P_ab/∂F_cd = μ δac δbd + (μ − λ ln J) G_ad G_cb + λ G_ab G_cd,  G = F⁻ᵀ
  // (from ∂ln J/∂F = G and ∂G_ab/∂F_cd = −G_ad G_cb).
  const Mat3 G = F.inverse().transpose();
  const Real c1 = mu - lambda * std::log(F.determinant());
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      for (int c = 0; c < 3; ++c)
        for (int d = 0; d < 3; ++d)
          A(3 * a + b, 3 * c + d) = (a == c && b == d ? mu : Real(0)) + c1 * G(a, d) * G(c, b) +
                                    lambda * G(a, b) * G(c, d);
  return A;
}

Mat3 cauchy_stress(const Mat3& F, const Mat3& first_piola) {
  return first_piola * F.transpose() / F.determinant();
}

}  // namespace latmpm::statics
