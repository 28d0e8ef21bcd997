// Linear elastic material with small-strain increments and the Jaumann (objective) stress
// rate: σ̇ = λ tr(D) I + 2μ D + W σ − σ W, D = sym L, W = skew L (Paper A's linear elastic
// model; the Jaumann term keeps rigid rotations stress-free). Explicit update over dt.
#pragma once
#include "mpm/deformation.hpp"
#include "mpm/material.hpp"

namespace latmpm::mpm {

struct LinearElastic {
  Real lambda = 0, mu = 0;  // Lamé parameters, Pa
  Real young = 0, poisson = 0;
  Real density = 0;         // kg/m³, mass scaling included

  static LinearElastic from(const MaterialParameters& m, Real mass_scaling) {
    return {m.lame_lambda(), m.shear_modulus(), m.young_modulus, m.poisson_ratio,
            m.density * mass_scaling};
  }

  template <class T>
  void update_stress(const Deformation<T>& d, Stress<T>& s) const {
    const auto& L = d.velocity_gradient;
    const Real dt = d.dt;
    // D and W in components; the Voigt order is xx yy zz yz xz xy.
    const T dxx = L[0][0], dyy = L[1][1], dzz = L[2][2];
    const T dyz = Real(0.5) * (L[1][2] + L[2][1]), dxz = Real(0.5) * (L[0][2] + L[2][0]),
            dxy = Real(0.5) * (L[0][1] + L[1][0]);
    const T wyz = Real(0.5) * (L[1][2] - L[2][1]), wxz = Real(0.5) * (L[0][2] - L[2][0]),
            wxy = Real(0.5) * (L[0][1] - L[1][0]);
    const T tr = lambda * (dxx + dyy + dzz);
    // Wσ − σW for symmetric σ, W = [[0, wxy, wxz], [−wxy, 0, wyz], [−wxz, −wyz, 0]].
    const T sxx = s[0], syy = s[1], szz = s[2], syz = s[3], sxz = s[4], sxy = s[5];
    const T rxx = 2 * (wxy * sxy + wxz * sxz);
    const T ryy = 2 * (-wxy * sxy + wyz * syz);
    const T rzz = 2 * (-wxz * sxz - wyz * syz);
    const T ryz = -wxy * sxz + wyz * (szz - syy) - wxz * sxy;
    const T rxz = wxy * syz + wxz * (szz - sxx) - wyz * sxy;
    const T rxy = wxy * (syy - sxx) + wxz * syz + wyz * sxz;
    s[0] = sxx + dt * (tr + 2 * mu * dxx + rxx);
    s[1] = syy + dt * (tr + 2 * mu * dyy + ryy);
    s[2] = szz + dt * (tr + 2 * mu * dzz + rzz);
    s[3] = syz + dt * (2 * mu * dyz + ryz);
    s[4] = sxz + dt * (2 * mu * dxz + rxz);
    s[5] = sxy + dt * (2 * mu * dxy + rxy);
  }

  // Dilatational wave speed squared (λ + 2μ)/ρ, m²/s² (initial density: conservative).
  Real wave_speed_squared(Real /*jacobian*/) const { return (lambda + 2 * mu) / density; }

  // Strain energy per reference volume, J/m³: ½ σ:ε J with ε = C⁻¹σ the elastic strain,
  // σ:C⁻¹σ = ((1+ν) σ:σ − ν (tr σ)²)/E (exact for small strains).
  template <class T>
  T strain_energy_density(const Deformation<T>& d, const Stress<T>& s) const {
    const T tr = s[0] + s[1] + s[2];
    const T ss = s[0] * s[0] + s[1] * s[1] + s[2] * s[2] + 2 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]);
    return (Real(0.5) / young) * d.jacobian * ((1 + poisson) * ss - poisson * tr * tr);
  }
};

}  // namespace latmpm::mpm
