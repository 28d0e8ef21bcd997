// Compressible neo-Hookean material (Bonet & Wood, Nonlinear Continuum Mechanics, Eq. 5.28
// and 5.29; Paper B Eq. 12 uses the same energy for its elastic part):
//   ψ = μ/2 (tr b − 3) − μ ln J + λ/2 (ln J)²,   σ = [μ (b − I) + λ ln J I] / J,   b = F Fᵀ.
// Hyperelastic: the stress depends on F only, so it needs no rate and no history.
#pragma once
#include <cmath>

#include "mpm/deformation.hpp"
#include "mpm/material.hpp"

namespace latmpm::mpm {

struct NeoHookean {
  Real lambda = 0, mu = 0;  // Lamé parameters, Pa
  Real density = 0;         // kg/m³, mass scaling included

  static NeoHookean from(const MaterialParameters& m, Real mass_scaling) {
    return {m.lame_lambda(), m.shear_modulus(), m.density * mass_scaling};
  }

  template <class T>
  void update_stress(const Deformation<T>& d, Stress<T>& s) const {
    const auto& F = d.f_new;
    auto b = [&](int i, int j) { return F[i][0] * F[j][0] + F[i][1] * F[j][1] + F[i][2] * F[j][2]; };
    const T inv_j = 1 / d.jacobian;
    const T pressure_term = lambda * num::log(d.jacobian);
    s[0] = inv_j * (mu * (b(0, 0) - 1) + pressure_term);
    s[1] = inv_j * (mu * (b(1, 1) - 1) + pressure_term);
    s[2] = inv_j * (mu * (b(2, 2) - 1) + pressure_term);
    s[3] = inv_j * mu * b(1, 2);
    s[4] = inv_j * mu * b(0, 2);
    s[5] = inv_j * mu * b(0, 1);
  }

  // Dilatational wave speed squared from the tangent modulus at J, m²/s²:
  // (λ + 2(μ − λ ln J)) / ρ0, which grows in compression; never below the small-strain value.
  Real wave_speed_squared(Real jacobian) const {
    const Real stiffening = jacobian < 1 ? -2 * lambda * std::log(jacobian) : Real(0);
    return (lambda + 2 * mu + stiffening) / density;
  }

  template <class T>
  T strain_energy_density(const Deformation<T>& d, const Stress<T>& /*s*/) const {
    const auto& F = d.f_new;
    T trace_b = F[0][0] * F[0][0];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if (i || j) trace_b += F[i][j] * F[i][j];
    const T log_j = num::log(d.jacobian);
    return Real(0.5) * mu * (trace_b - 3) - mu * log_j + Real(0.5) * lambda * log_j * log_j;
  }
};

}  // namespace latmpm::mpm
