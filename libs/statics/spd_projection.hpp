// The positive-definite fix of projected Newton (Teran et al. 2005; paper C Sec. 3.3): a
// point's tangent ∂P/∂F is replaced by its projection onto the positive semidefinite cone
// (negative eigenvalues clamped to zero). The point's Hessian over the nodal displacements
// is Bᵀ A B with B the linear map u ↦ F, so a semidefinite A makes every point's
// contribution, and their sum, semidefinite: the Newton direction is a descent direction.
// Projecting the 9×9 tangent instead of the (3n)×(3n) point Hessian is the cheaper choice
// that keeps this property (paper C does not say which it projects).
#pragma once
#include "statics/elastic_energy.hpp"

namespace latmpm::statics {

// The nearest positive semidefinite matrix to the symmetric part of A (Frobenius norm).
Mat9 project_to_semidefinite(const Mat9& A);

}  // namespace latmpm::statics
