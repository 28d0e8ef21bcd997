// The compliance of a multi-density design and its sensitivity, paper C Sec. 3.2-3.3: the
// active quadrature points become the material points of a static MPM problem
// (libs/statics: narrow band of grid nodes, linear shape functions as in Eq. 29-31), each
// with Young's modulus E_q = E_min + ρ_q^p (E − E_min) (SIMP-like power, Sec. 3.3), solved
// in one Newton step (linear elasticity). The compliance is the elastic potential of
// Eq. (25), C = Σ_q V_q ψ(F_q; E_q) = ½ fᵀu at equilibrium, and its sensitivity the closed
// form of Eq. (21)-(22): ∂C/∂ρ_q = −V_q (∂E_q/∂ρ_q / E) ψ(F_q; E).
// Neo-Hookean (paper C Sec. 3.3, 4.3): the same C (the elastic potential), the equilibrium
// solved by projected Newton, and the sensitivity of Eq. (19) by the adjoint: with
// ∂C/∂u = f_int(u) = f at equilibrium, K_T λ = f (K_T the true tangent, the static solver's
// unprojected Hessian) gives
//   ∂C/∂ρ_q = V_q (∂E_q/∂ρ_q / E) [ψ(F_q; E) − P(F_q; E) : ∇λ_q],
// which is the closed form again where λ = u (linear elasticity: P : ∇u = 2ψ). The
// neo-Hookean solve adds the static solver's affine stabilisation (β = 0.1 μ): its energy
// is part of C and of the gradient (compliance.cpp).
// Inactive points (outside the narrow band) carry no material and no unknowns.
#pragma once
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "mpm/material.hpp"
#include "optimize/design_grid.hpp"
#include "optimize/load_case.hpp"

namespace latmpm::optimize {

struct SimpMaterial {
  mpm::MaterialKind model = mpm::MaterialKind::linear_elastic;  // or neo_hookean
  Real young_modulus = 0;   // E of the solid, Pa
  Real poisson_ratio = 0;   // ν
  Real penalty = 3;         // p
  Real weak_ratio = 0;      // E_min / E: 0 for the narrow band, 1e-9 for weak-material fill

  Real modulus(Real rho) const;             // E_q, Pa
  Real modulus_derivative(Real rho) const;  // ∂E_q/∂ρ_q, Pa
};

struct ComplianceResult {
  Real compliance = 0;          // C, J
  Real external_work = 0;       // ½ fᵀu, J (equals C at equilibrium)
  std::vector<Real> gradient;   // ∂C/∂ρ_q per quadrature point (0 where inactive), J
  std::vector<Vec3> point_displacement;  // u at the active points (0 where inactive), m
  size_t unknowns = 0;          // free displacement components of the solve
  size_t active_points = 0;
  int newton_iterations = 0;
  int load_steps = 0;           // neo-Hookean: load steps from rest (0: the whole load at once)
  bool from_guess = false;      // neo-Hookean: converged from the guess under the whole load
};

// A nonlinear equilibrium's nodal displacements by grid node, the start of the next
// design's solve (a design iteration changes the densities and the band a little).
struct EquilibriumGuess {
  std::unordered_map<int64_t, Vec3> node_displacement;  // m, keyed by grid node
  static int64_t key(int i, int j, int k) {
    return (int64_t(i + (1 << 20)) << 42) | (int64_t(j + (1 << 20)) << 21) | int64_t(k + (1 << 20));
  }
};

// density: ρ_q per quadrature point of `grid`; active: which points are simulated (every
// loaded point must be active). Throws NumericalError when the solve fails.
// guess (neo-Hookean only; may be null): on entry the start of the equilibrium solve under
// the whole load (nodes it lacks start at the mean of their neighbours that it has); when
// that fails, the load is applied in adaptive steps from rest (statics/load_continuation.hpp).
// On return it holds this equilibrium.
ComplianceResult evaluate_compliance(const DesignGrid& grid, const std::vector<Real>& density,
                                     const std::vector<char>& active, const LoadCase& load_case,
                                     const SimpMaterial& material, EquilibriumGuess* guess = nullptr);

}  // namespace latmpm::optimize
