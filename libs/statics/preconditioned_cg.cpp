#include "statics/preconditioned_cg.hpp"

#include <cmath>

namespace latmpm::statics {

KrylovResult preconditioned_cg(const SparseMatrix& K, const Vector& b,
                               const std::function<Vector(const Vector&)>& apply_inverse, Real tolerance,
                               int max_iterations, Vector& x) {
  KrylovResult result;
  x = Vector::Zero(b.size());
  const Real norm_b = b.norm();
  if (norm_b == 0) {
    result.outcome = KrylovOutcome::solved;
    return result;
  }
  // Hestenes–Stiefel PCG (Saad, Iterative Methods for Sparse Linear Systems, Alg. 9.1).
  Vector r = b;
  Vector z = apply_inverse(r);
  Vector p = z;
  Real rz = r.dot(z);
  Vector Kp(b.size());
  while (result.iterations < max_iterations) {
    Kp.noalias() = K * p;
    const Real curvature = p.dot(Kp);
    ++result.iterations;
    if (!(curvature > 0)) {
      result.outcome = KrylovOutcome::negative_curvature;
      break;
    }
    const Real alpha = rz / curvature;
    x += alpha * p;
    r -= alpha * Kp;
    if (r.norm() <= tolerance * norm_b) {
      result.outcome = KrylovOutcome::solved;
      break;
    }
    z = apply_inverse(r);
    const Real rz_next = r.dot(z);
    p = z + (rz_next / rz) * p;
    rz = rz_next;
  }
  result.relative_residual = (K * x - b).norm() / norm_b;
  // The recurrence's residual drifts from the true one by round-off: the true one decides.
  if (result.outcome == KrylovOutcome::solved && !(result.relative_residual <= 10 * tolerance))
    result.outcome = KrylovOutcome::not_converged;
  return result;
}

}  // namespace latmpm::statics
