// Linear elastic material with small-strain increments and the Jaumann (objective) stress
// rate: σ̇ = λ tr(D) I + 2μ D + W σ − σ W, D = sym L, W = skew L (Paper A's linear elastic
// model; the Jaumann term keeps rigid rotations stress-free). Explicit update over dt.
//
// Its energy. A hypoelastic model has no stored-energy function: ½ σ:C⁻¹σ J (the
// complementary energy of the current stress) is the energy put in only for small strains.
// Where points are squeezed or sheared far (a lattice folding under an impact: J < 0.8) it
// misses part of the stress work by up to ~15 % of the energy put in, and the energy balance
// showed that as a loss that came back on unloading (docs/impact.md, "The energy balance").
// So each point carries the stress work it has taken, w = ∫ J σ:D dt per reference volume
// (J/m³), integrated by the trapezoid rule over each step; that is the model's energy, the
// work-conjugate one of the balance. For small strains w = ½ σ:ε to round-off (the trapezoid
// is exact for the linear law).
#pragma once
#include <array>

#include "mpm/deformation.hpp"
#include "mpm/material.hpp"
#include "mpm/material_history.hpp"

namespace latmpm::mpm {

struct LinearElastic {
  Real lambda = 0, mu = 0;  // Lamé parameters, Pa
  Real young = 0, poisson = 0;
  Real density = 0;         // kg/m³, mass scaling included

  static LinearElastic from(const MaterialParameters& m, Real mass_scaling) {
    return {m.lame_lambda(), m.shear_modulus(), m.young_modulus, m.poisson_ratio,
            m.density * mass_scaling};
  }

  // The stress work w above (material_history.hpp). A checkpoint written before it existed
  // lacks the column: each point's w is then its complementary energy (history_from_state),
  // the energy that run reported.
  static constexpr std::array<HistoryVariable, 1> history{{{"linear_elastic_stress_work", 0, true}}};

  // The stress update with w: J σ:D over the step by the trapezoid rule between the stress
  // (and J) before and after.
  template <class T>
  void update_stress(const Deformation<T>& d, Stress<T>& s, T* work) const {
    const T power_old = d.jacobian_old * stress_power_per_volume(d.velocity_gradient, s);
    update_stress(d, s);
    const T power_new = d.jacobian * stress_power_per_volume(d.velocity_gradient, s);
    work[0] += Real(0.5) * d.dt * (power_old + power_new);
  }

  // w for a point whose history is unknown (a checkpoint without the column): the
  // complementary energy of its stress, exact for small strains.
  void history_from_state(const Deformation<Real>& d, const Stress<Real>& s, Real* work) const {
    work[0] = strain_energy_density(d, s);
  }

  // The rate form alone (no energy bookkeeping).
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

  // Strain energy per reference volume, J/m³: the stress work w (above).
  template <class T>
  T strain_energy_density(const Deformation<T>&, const Stress<T>&, const T* work) const {
    return work[0];
  }

  // The complementary energy, ½ σ:ε J with ε = C⁻¹σ the elastic strain,
  // σ:C⁻¹σ = ((1+ν) σ:σ − ν (tr σ)²)/E: the strain energy for small strains.
  template <class T>
  T strain_energy_density(const Deformation<T>& d, const Stress<T>& s) const {
    const T tr = s[0] + s[1] + s[2];
    const T ss = s[0] * s[0] + s[1] * s[1] + s[2] * s[2] + 2 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]);
    return (Real(0.5) / young) * d.jacobian * ((1 + poisson) * ss - poisson * tr * tr);
  }

 private:
  // σ:D for symmetric σ in Voigt order (D = sym L).
  template <class T>
  static T stress_power_per_volume(const T (&L)[3][3], const Stress<T>& s) {
    return s[0] * L[0][0] + s[1] * L[1][1] + s[2] * L[2][2] + s[3] * (L[1][2] + L[2][1]) +
           s[4] * (L[0][2] + L[2][0]) + s[5] * (L[0][1] + L[1][0]);
  }
};

}  // namespace latmpm::mpm
