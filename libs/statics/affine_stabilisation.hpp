// Stabilisation of the point quadrature's zero-energy modes (docs/statics.md): nodal
// displacement fields that change no F_p (products of splines vanishing at every sample
// plane where a part is two cells thick; near-mechanisms around weakly connected points of
// voxelized struts) have no stiffness, or a negative one under compression, so the true
// tangent is singular or indefinite although the structure is stable. Paper C is silent.
//
// The added energy penalises, per point, how far its stencil's nodal displacements are
// from the affine field the point carries (u(X_p) and F_p, APIC's view of a point):
//   E_s = Σ_p c_p/2 Σ_k S_kp |u_k − u(X_p) − (F_p − I)(X_k − X_p)|²,  c_p = β μ_p V_p / h²
// with u(X_p) = Σ_j S_jp u_j. It vanishes for every nodal field that is affine on the
// stencil — rigid motions and uniform strains included, so the patch test and rigid-body
// invariance hold exactly — and is quadratic in u with one constant, positive semidefinite
// Hessian (the same on each displacement component). A field that is affine on every
// stencil of a connected body is affine on the body, so only those are left without
// stiffness. β is dimensionless (a fraction of the shear modulus); its effect on the
// stiffness of bending-dominated parts is measured in docs/statics.md.
#pragma once
#include <vector>

#include "statics/band_matrix.hpp"

namespace latmpm::statics {

// One value per node pair (BandMatrix::assemble_blocks order): the scalar Hessian B of E_s
// for the per-point coefficients c_p (N/m); the Hessian over all unknowns is B ⊗ I₃.
std::vector<Real> affine_stabilisation_blocks(const BandMatrix& matrix, const NarrowBand& band,
                                              const std::vector<Real>& coefficient);

}  // namespace latmpm::statics
