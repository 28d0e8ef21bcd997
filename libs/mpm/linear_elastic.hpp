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

  [[gnu::always_inline]] void update_stress(const Deformation& d, SymTensor& s) const {
    const Mat3& L = d.velocity_gradient;
    const Real dt = d.dt;
    // D and W in components; the Voigt order is xx yy zz yz xz xy.
    const Real dxx = L(0, 0), dyy = L(1, 1), dzz = L(2, 2);
    const Real dyz = Real(0.5) * (L(1, 2) + L(2, 1)), dxz = Real(0.5) * (L(0, 2) + L(2, 0)),
               dxy = Real(0.5) * (L(0, 1) + L(1, 0));
    const Real wyz = Real(0.5) * (L(1, 2) - L(2, 1)), wxz = Real(0.5) * (L(0, 2) - L(2, 0)),
               wxy = Real(0.5) * (L(0, 1) - L(1, 0));
    const Real tr = lambda * (dxx + dyy + dzz);
    // Wσ − σW for symmetric σ, W = [[0, wxy, wxz], [−wxy, 0, wyz], [−wxz, −wyz, 0]].
    const Real sxx = s[0], syy = s[1], szz = s[2], syz = s[3], sxz = s[4], sxy = s[5];
    const Real rxx = 2 * (wxy * sxy + wxz * sxz);
    const Real ryy = 2 * (-wxy * sxy + wyz * syz);
    const Real rzz = 2 * (-wxz * sxz - wyz * syz);
    const Real ryz = -wxy * sxz + wyz * (szz - syy) - wxz * sxy;  // (Wσ − σW)_yz
    const Real rxz = wxy * syz + wxz * (szz - sxx) - wyz * sxy;   // (Wσ − σW)_xz
    const Real rxy = wxy * (syy - sxx) + wxz * syz + wyz * sxz;   // (Wσ − σW)_xy
    s[0] += dt * (tr + 2 * mu * dxx + rxx);
    s[1] += dt * (tr + 2 * mu * dyy + ryy);
    s[2] += dt * (tr + 2 * mu * dzz + rzz);
    s[3] += dt * (2 * mu * dyz + ryz);
    s[4] += dt * (2 * mu * dxz + rxz);
    s[5] += dt * (2 * mu * dxy + rxy);
  }

  // Dilatational wave speed squared (λ + 2μ)/ρ, m²/s² (initial density: conservative).
  Real wave_speed_squared(Real /*jacobian*/) const { return (lambda + 2 * mu) / density; }

  // Strain energy per reference volume, J/m³: ½ σ:ε J with ε = C⁻¹σ the elastic strain,
  // σ:C⁻¹σ = ((1+ν) σ:σ − ν (tr σ)²)/E (exact for small strains).
  Real strain_energy_density(const Mat3& /*f*/, Real jacobian, const SymTensor& s) const {
    const Real tr = s[0] + s[1] + s[2];
    const Real ss = s[0] * s[0] + s[1] * s[1] + s[2] * s[2] + 2 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]);
    return Real(0.5) * jacobian * ((1 + poisson) * ss - poisson * tr * tr) / young;
  }
};

}  // namespace latmpm::mpm
