// Linear elastic material with small-strain increments and the Jaumann (objective) stress
// rate: σ̇ = λ tr(D) I + 2μ D + W σ − σ W, D = sym L, W = skew L (Paper A's linear elastic
// model; the Jaumann term keeps rigid rotations stress-free). Explicit update over dt.
//
// Its energy. A hypoelastic model has no stored-energy function: ½ σ:C⁻¹σ J (the
// complementary energy of the current stress) is the energy put in only for small strains.
// Where points are squeezed or sheared far (a lattice folding under an impact: J < 0.8) it
// misses part of the stress work by up to ~15 % of the energy put in, and the energy balance
// shows that as a loss that comes back on unloading (docs/impact.md, "The energy balance").
// So each point carries the stress work it has taken beyond that measure,
//   δ = ∫ J σ:D dt − ½ σ:C⁻¹σ J   (per reference volume, J/m³; zero at the start),
// the work integrated by the trapezoid rule over each step, and the model's energy is
// ½ σ:C⁻¹σ J + δ = ∫ J σ:D dt: the stress power's integral, the work-conjugate energy of
// the balance. For small strains δ stays at round-off (the trapezoid is exact for the
// linear law), so the energy equals ½ σ:ε as before.
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

  // The stress work beyond the complementary energy, δ above (material_history.hpp). A
  // checkpoint written before it existed resumes with δ = 0, i.e. from the complementary
  // energy the run reported until then.
  static constexpr std::array<HistoryVariable, 1> history{{{"linear_elastic_work_excess", 0, true}}};

  // The stress update with δ: the work J σ:D over the step by the trapezoid rule between
  // the stress (and J) before and after, less the change of the complementary energy.
  template <class T>
  void update_stress(const Deformation<T>& d, Stress<T>& s, T* work_excess) const {
    const auto& L = d.velocity_gradient;
    const Real dt = d.dt;
    // J before the step: F_new = (I + dt L) F_old.
    T step[3][3];
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) step[r][c] = (r == c ? T{} + Real(1) : T{}) + dt * L[r][c];
    const T j_old = d.jacobian / determinant(step);
    const T power_old = j_old * stress_power_per_volume(L, s);
    const T energy_old = complementary_energy_density(j_old, s);
    update_stress(d, s);
    const T power_new = d.jacobian * stress_power_per_volume(L, s);
    work_excess[0] += Real(0.5) * dt * (power_old + power_new) - (complementary_energy_density(d.jacobian, s) - energy_old);
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

  // Strain energy per reference volume, J/m³: the stress work ∫ J σ:D dt, i.e. the
  // complementary energy plus the point's δ (above).
  template <class T>
  T strain_energy_density(const Deformation<T>& d, const Stress<T>& s, const T* work_excess) const {
    return complementary_energy_density(d.jacobian, s) + work_excess[0];
  }

  // The complementary energy alone, ½ σ:ε J with ε = C⁻¹σ the elastic strain,
  // σ:C⁻¹σ = ((1+ν) σ:σ − ν (tr σ)²)/E: the strain energy for small strains.
  template <class T>
  T strain_energy_density(const Deformation<T>& d, const Stress<T>& s) const {
    return complementary_energy_density(d.jacobian, s);
  }

 private:
  template <class T>
  T complementary_energy_density(const T& jacobian, const Stress<T>& s) const {
    const T tr = s[0] + s[1] + s[2];
    const T ss = s[0] * s[0] + s[1] * s[1] + s[2] * s[2] + 2 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]);
    return (Real(0.5) / young) * jacobian * ((1 + poisson) * ss - poisson * tr * tr);
  }
  // σ:D for symmetric σ in Voigt order (D = sym L).
  template <class T>
  static T stress_power_per_volume(const T (&L)[3][3], const Stress<T>& s) {
    return s[0] * L[0][0] + s[1] * L[1][1] + s[2] * L[2][2] + s[3] * (L[1][2] + L[2][1]) +
           s[4] * (L[0][2] + L[2][0]) + s[5] * (L[0][1] + L[1][0]);
  }
};

}  // namespace latmpm::mpm
