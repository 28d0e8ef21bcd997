// Paper B's finite-strain J2 plasticity (j2_plasticity.hpp) in the form the solver's
// material kernels call: update_stress / strain_energy_density over Deformation<T> for
// T = Real or Pack (eight particles, one per lane), with the history as one T per variable.
// The return mapping is scalar (an eigen-decomposition and a small Newton), so a Pack is
// updated lane by lane. History, in this order: the elastic left Cauchy–Green tensor be
// (Voigt xx yy zz yz xz xy, starting at I), the plastic arc length α, and the plastic work
// Σ Δα y(α) per reference volume (J/m³) for the energy balance.
//
// Lanes whose be is zero (the kernels' idle lanes, which hold no particle) get zero stress
// and energy. A lane whose update fails (det f ≤ 0, no convergence) gets NaN stress, which
// the solver's fault check reports with the step and the particle.
#pragma once
#include <array>
#include <cmath>
#include <limits>
#include <type_traits>

#include "mpm/deformation.hpp"
#include "mpm/j2_plasticity.hpp"
#include "mpm/material.hpp"
#include "mpm/material_history.hpp"

namespace latmpm::mpm {

struct J2Plastic {
  J2Parameters parameters;
  Real density = 0;  // kg/m³, mass scaling included

  // The particle history columns (material_history.hpp), in the order update_stress uses.
  static constexpr std::array<HistoryVariable, 8> history{{{"j2_be_xx", 1},
                                                           {"j2_be_yy", 1},
                                                           {"j2_be_zz", 1},
                                                           {"j2_be_yz", 0},
                                                           {"j2_be_xz", 0},
                                                           {"j2_be_xy", 0},
                                                           {"j2_alpha", 0},
                                                           {"j2_plastic_work", 0}}};
  // j2_plastic_work: the energy balance's plastic dissipation (material_history.hpp).
  static constexpr size_t dissipation_history = 7;

  static J2Plastic from(const MaterialParameters& m, Real mass_scaling) {
    return {j2_parameters(m), m.density * mass_scaling};
  }

  template <class T>
  void update_stress(const Deformation<T>& d, Stress<T>& s, T* values) const {
    for (int q = 0; q < lanes<T>; ++q) update_lane(d, s, values, q);
  }

  // ψ(be) of Eq. 12 per reference volume, J/m³ (the stress argument is not needed).
  template <class T>
  T strain_energy_density(const Deformation<T>& /*d*/, const Stress<T>& /*s*/, const T* values) const {
    T out{};
    for (int q = 0; q < lanes<T>; ++q) {
      const J2State state = lane_state(values, q);
      set(out, q, idle(state) ? Real(0) : j2_stored_energy(parameters, state));
    }
    return out;
  }

  // Dilatational wave speed squared at be = I, (λ + 2μ)/ρ, m²/s². Eq. 12's tangent changes
  // with the elastic strains only, which a metal keeps below y/E ≈ 1 %: a few per cent,
  // inside the time step's CFL margin, and independent of the total J.
  Real wave_speed_squared(Real /*jacobian*/) const {
    return (parameters.lame_lambda() + 2 * parameters.shear_modulus()) / density;
  }

 private:
  template <class T>
  static constexpr int lanes = std::is_same_v<T, Real> ? 1 : pack_width;

  static Real get(const Real& x, int) { return x; }
  static Real get(const Pack& x, int q) { return x[q]; }
  static void set(Real& x, int, Real v) { x = v; }
  static void set(Pack& x, int q, Real v) { x[q] = v; }

  template <class T>
  static J2State lane_state(const T* values, int q) {
    J2State state;
    for (int c = 0; c < 6; ++c) state.elastic_left_cauchy_green[c] = get(values[c], q);
    state.plastic_arc_length = get(values[6], q);
    return state;
  }
  static bool idle(const J2State& state) { return state.elastic_left_cauchy_green.head<3>().sum() == 0; }

  template <class T>
  void update_lane(const Deformation<T>& d, Stress<T>& s, T* values, int q) const {
    const J2State state = lane_state(values, q);
    if (idle(state)) {
      for (int c = 0; c < 6; ++c) set(s[c], q, 0);
      return;
    }
    Mat3 f;  // the step's relative deformation gradient, I + Δt L (paper B Eq. 6)
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) f(a, b) = (a == b) + d.dt * get(d.velocity_gradient[a][b], q);
    try {
      const J2Update u = j2_update(parameters, f, state);
      for (int c = 0; c < 6; ++c) set(s[c], q, u.cauchy[c]), set(values[c], q, u.state.elastic_left_cauchy_green[c]);
      set(values[6], q, u.state.plastic_arc_length);
      set(values[7], q, get(values[7], q) + u.dissipation);
    } catch (const std::exception&) {
      for (int c = 0; c < 6; ++c) set(s[c], q, std::numeric_limits<Real>::quiet_NaN());
    }
  }
};

}  // namespace latmpm::mpm
