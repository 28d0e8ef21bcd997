// DDMP's stabilization of the smoothed gradient's null space (our addition to Paper A's
// DDMP; docs/solver.md, "DDMP": the bullet "The smoothed gradient's null space is
// stabilized" and "DDMP column: the cause, and the stabilization").
//
// Why. Eq. 7's smoothed part is a central difference of the nodal velocities:
// ∫ S_j ∂_x S_i dV = h² D(i_x − j_x) M(i_y − j_y) M(i_z − j_z) with D(0) = 0 (shape_ddmp.hpp),
// zero for every node i in j's own x plane. So a nodal velocity that alternates from node
// plane to node plane along the direction it differentiates — an axial v_z ∝ (−1)^{i_z}, or a sideways zig-zag
// v_x ∝ (−1)^{i_z} along a column — has no smoothed strain rate at all. Only the α part sees
// it, and Eq. 5's α is at most 0.23 and zero on every cell face, so these patterns cost almost
// no strain energy: the zero-energy modes of nodal integration (Puso, Chen, Zywicz & Elmer
// 2008, "Meshfree and finite element nodal integration methods", IJNME 74). The points move
// with the linear S_i, which do see the patterns; F, integrated from L̄, does not. On paper A's
// buckled column (t = 1.6 mm, 0.4 mm cells) the points' positions showed 1.45 times the strain
// energy their F held (uGIMP: 0.96), their sideways positions carried a zig-zag of period 2h
// eight times uGIMP's, and its post-buckling load over the last quarter of 3 mm of travel was
// 0.917 of uGIMP's (0.892 at 0.2 mm; docs/solver.md, "DDMP column: the cause").
//
// What. Each point of a deformable body carries a stabilization stress σ_s, elastic in the
// difference between its plain linear-MPM velocity gradient L = Σ_i v_i ⊗ ∇S_i(x_p) and
// Eq. 7's L̄, with β times the body's small-strain moduli, rotated with L̄'s spin (Jaumann):
//   σ_s ← σ_s + dt [β C : sym(L − L̄) + W̄ σ_s − σ_s W̄],
// and puts on the nodes the force conjugate to that rate, f_i = −V σ_s (∇S_i − ∇̄S_i)
// = −V (1 − α) σ_s (∇S_i − Σ_j S_j/V_j ∫ S_j ∇S_i dV): the local part on the cell's 8 nodes,
// the smoothed part through the nodal stress σ^d (ddmp_grid.hpp) with −σ_s (scatter_bucket
// adds each to the point's own σ parts: one plain-gradient scatter of −V (α σ + (1 − α) σ_s)
// and one corner scatter of σ − σ_s). For a linear
// nodal velocity field (rigid motion included; the small-mass read-back extends a linear
// field exactly past free surfaces) L = L̄ and σ_s stays zero;
// for the null-space patterns it gives back β times linear MPM's stiffness. Its energy,
// ½ σ_s : (βC)⁻¹ : σ_s per current volume, is booked as strain energy so the balance closes.
// Eq. 8 (the gradient's sums) and mass, momentum and the smoothed gradient itself are
// unchanged. β = 0 (`grid.ddmp_stabilization = 0`) is Paper A's DDMP as printed; β ≤ 1, so
// the zig-zag is never stiffer than in linear MPM and the material's stable step holds. σ_s is
// elastic for every material model: with J2 it does not yield (not measured on a J2 scene).
#pragma once
#include "mpm/linear_elastic.hpp"
#include "mpm/shape_ddmp.hpp"

namespace latmpm::mpm {

// The stabilization's moduli for a body: β times the body's small-strain λ, μ (E, ν).
inline LinearElastic ddmp_stabilization_moduli(const MaterialParameters& m, Real beta) {
  LinearElastic s = LinearElastic::from(m, 1);
  s.lambda *= beta;
  s.mu *= beta;
  s.young *= beta;
  return s;
}

// The point's plain linear-MPM gradient: its cell's stencil with ∇S_i in place of α ∇S_i.
inline DdmpCornerStencil ddmp_plain_gradient_stencil(const DdmpCornerStencil& st, Real inv_h) {
  DdmpCornerStencil plain = st;
  for (int a = 0; a < 3; ++a) {
    plain.dw[0][a] = -inv_h;
    plain.dw[1][a] = inv_h;
  }
  return plain;
}

// σ_s over one step from the point's plain L and Eq. 7's L̄ (both 1/s, [row][column]).
inline void update_ddmp_stabilization_stress(const LinearElastic& moduli, const Real (&plain)[3][3],
                                             const Real (&smoothed)[3][3], Real dt, ParticleSymTensor& stress) {
  // LinearElastic's Jaumann update splits its L into sym and skew: give it sym(L − L̄) + skew(L̄).
  Deformation<Real> d;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      const Real difference = Real(0.5) * ((plain[r][c] - smoothed[r][c]) + (plain[c][r] - smoothed[c][r]));
      const Real spin = Real(0.5) * (smoothed[r][c] - smoothed[c][r]);
      d.velocity_gradient[r][c] = difference + spin;
    }
  d.dt = dt;
  Real s[6];
  for (int k = 0; k < 6; ++k) s[k] = stress[k];
  moduli.update_stress(d, s);
  for (int k = 0; k < 6; ++k) stress[k] = ParticleReal(s[k]);
}

// Its energy per reference volume, J/m³ (jacobian: the point's J).
inline Real ddmp_stabilization_energy_density(const LinearElastic& moduli, const ParticleSymTensor& stress,
                                              Real jacobian) {
  Deformation<Real> d{};
  d.jacobian = jacobian;
  Real s[6];
  for (int k = 0; k < 6; ++k) s[k] = stress[k];
  return moduli.strain_energy_density(d, s);
}

}  // namespace latmpm::mpm
