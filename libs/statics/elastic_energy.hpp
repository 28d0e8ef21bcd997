// Hyperelastic energy densities of the static solver, as functions of the deformation
// gradient F only (total Lagrangian: the reference configuration is the point set):
// ψ(F) (J/m³ of reference volume), the first Piola–Kirchhoff stress P = ∂ψ/∂F (Pa) and
// the tangent A = ∂P/∂F (Pa), the per-point pieces of paper C Eq. (33) and (34).
//   linear elastic: ψ = μ ε:ε + λ/2 (tr ε)², ε = sym(F − I)  (small strain: quadratic in u,
//                   so projected Newton takes one step, paper C Sec. 3.3)
//   neo-Hookean:    ψ = μ/2 (tr FᵀF − 3) − μ ln J + λ/2 (ln J)²  (Bonet & Wood Eq. 5.28,
//                   the energy libs/mpm/neo_hookean.hpp integrates in the explicit solver)
// Matrices over F are flattened row-major: index 3a + b holds F_ab.
#pragma once
#include <Eigen/Core>

#include "mpm/material.hpp"
#include "mpm/real.hpp"

namespace latmpm::statics {

using mpm::Mat3;
using mpm::Real;
using mpm::Vec3;
using Mat9 = Eigen::Matrix<Real, 9, 9>;

struct ElasticEnergy {
  mpm::MaterialKind kind = mpm::MaterialKind::linear_elastic;
  Real lambda = 0, mu = 0;  // Lamé parameters, Pa

  static ElasticEnergy from(const mpm::MaterialParameters& m);

  // The energy is finite only for det F > 0 (neo-Hookean); callers keep F there.
  Real density(const Mat3& F) const;        // ψ, J/m³
  Mat3 first_piola(const Mat3& F) const;    // P = ∂ψ/∂F, Pa
  Mat9 tangent(const Mat3& F) const;        // A_(ab)(cd) = ∂P_ab/∂F_cd, Pa
  // Whether the energy is quadratic in F (its tangent does not depend on F).
  bool is_quadratic() const { return kind == mpm::MaterialKind::linear_elastic; }
};

// Cauchy stress σ = P Fᵀ / det F (Pa), to compare with the explicit solver's stress.
Mat3 cauchy_stress(const Mat3& F, const Mat3& first_piola);

}  // namespace latmpm::statics
