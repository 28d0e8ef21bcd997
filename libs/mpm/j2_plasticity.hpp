// Finite-strain J2 (von Mises) plasticity of paper B (Sec. 3.3), as a pure function of one
// material point's deformation increment and history: it sees deformation and history, never
// a particle. Multiplicative split F = Fe·Fp (Eq. 11), Neo-Hooke energy of Fe (Eq. 12),
// yield function φ = sqrt(3/2) |dev τ| − y(α) (Eq. 9) with the hardening law
// y(α) = y∞ + (y0 − y∞) e^(−η α) + h α (Eq. 10), and the implicit exponential-map update
// Fe = exp(−Δα sqrt(3/2) n)·F·Fp_n⁻¹ of Eq. 13 with n = dev τ / |dev τ|.
//
// The history is the elastic left Cauchy–Green tensor be = Fe Feᵀ and the plastic arc
// length α (Simo 1992, CMAME 99:61; Simo & Hughes, Computational Inelasticity, Ch. 9):
// be carries everything of Fp the stress needs and, unlike Fe, needs no rotation bookkeeping.
// Plastic flow is isochoric (tr n = 0), so J = det F = sqrt(det be) and Cauchy σ = τ / J.
// Derivation and the choice of a 4-unknown Newton (Eq. 12 is not quadratic in the
// logarithmic stretches, so the return is not radial): docs/paper-b.md.
#pragma once
#include <string>

#include "mpm/real.hpp"

namespace latmpm::mpm {

struct J2Parameters {
  Real young_modulus = 0;     // E, Pa (the small-strain limit of Eq. 12)
  Real poisson_ratio = 0;     // ν, dimensionless, in (-1, 0.5)
  Real initial_yield = 0;     // y0, Pa
  Real saturation_yield = 0;  // y∞, Pa
  Real saturation_rate = 0;   // η, dimensionless (per unit plastic arc length)
  Real linear_hardening = 0;  // h, Pa

  Real lame_lambda() const;    // λ = Eν / ((1+ν)(1−2ν)), Pa
  Real shear_modulus() const;  // μ = E / (2(1+ν)), Pa
  Real yield_stress(Real alpha) const;     // y(α), Eq. 10, Pa
  Real hardening_modulus(Real alpha) const;  // y'(α), Pa
  // Throws InputError(where, field, problem) for a non-physical set (E ≤ 0, ν outside
  // (-1, 0.5), y0 ≤ 0, y∞ ≤ 0, η < 0, h < 0).
  void validate(const std::string& where) const;
};

// Published parameter sets (docs/paper-b.md gives the sources and the fits).
J2Parameters steel_42crmo4_400c();  // 42CrMo4 at 400 °C and 2661.9 1/s (paper B's specimen)
J2Parameters ti6al4v();             // Ti-6Al-4V at room temperature (metal lattices)

// History of one material point, in a plain struct.
struct J2State {
  SymTensor elastic_left_cauchy_green = (SymTensor() << 1, 1, 1, 0, 0, 0).finished();  // be, Voigt
  Real plastic_arc_length = 0;  // α
};

struct J2Update {
  J2State state;          // history at the end of the step
  SymTensor kirchhoff;    // τ, Pa (Voigt xx yy zz yz xz xy)
  SymTensor cauchy;       // σ = τ / J, Pa
  Real plastic_increment = 0;  // Δα = Δγ ≥ 0
  Real dissipation = 0;   // Δα·y(α_{n+1}): plastic work of the step per reference volume, J/m³
  int newton_iterations = 0;
};

// One step: the relative deformation gradient f = F_{n+1} F_n⁻¹ (= I + Δt·L in the explicit
// scheme, paper B Eq. 6) applied to the state at t_n. Throws NumericalError when det f ≤ 0
// or the return does not converge.
J2Update j2_update(const J2Parameters& p, const Mat3& relative_deformation, const J2State& previous);

// Stored energy ψ(be) of Eq. 12 per reference volume, J/m³ (J² = det be).
Real j2_stored_energy(const J2Parameters& p, const J2State& state);

}  // namespace latmpm::mpm
