// Conjugate gradients preconditioned by the Cholesky factor of an earlier matrix, for the
// Krylov steps of projected Newton (modified Newton with Krylov acceleration: the tangent of
// the next Newton step or load increment differs from the factorised one by the change of
// state since, so CG preconditioned by the old factor converges in a few iterations where a
// new factorisation costs the work of ~30 of them on the paper-size lattice; docs/statics.md
// "Krylov steps"). Written out rather than Eigen's ConjugateGradient because the Newton
// step needs what Eigen's does not report: a direction of non-positive curvature pᵀKp ≤ 0,
// which proves K not positive definite (the true tangent is then replaced by the projected
// one, as where a factorisation fails).
#pragma once
#include <functional>

#include "statics/band_matrix.hpp"

namespace latmpm::statics {

using Vector = Eigen::Matrix<Real, Eigen::Dynamic, 1>;

enum class KrylovOutcome { solved, not_converged, negative_curvature };

struct KrylovResult {
  KrylovOutcome outcome = KrylovOutcome::not_converged;
  int iterations = 0;
  Real relative_residual = 0;  // ‖K x − b‖ / ‖b‖, recomputed from x at the end
};

// Solves K x = b (K symmetric, both triangles stored) from x = 0 with the preconditioner
// z = M⁻¹ r, M symmetric positive definite, to ‖K x − b‖ ≤ tolerance ‖b‖ within
// max_iterations.
KrylovResult preconditioned_cg(const SparseMatrix& K, const Vector& b,
                               const std::function<Vector(const Vector&)>& apply_inverse, Real tolerance,
                               int max_iterations, Vector& x);

}  // namespace latmpm::statics
