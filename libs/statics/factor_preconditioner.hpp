// A Cholesky factor of an earlier matrix as the preconditioner of Eigen's ConjugateGradient
// on a nearby one (modified Newton with Krylov acceleration: the tangent of the next
// Newton step or load increment differs from the factorised one by the change of state
// since, so CG preconditioned by the old factor converges in a few iterations where a new
// factorisation costs the work of hundreds of them; docs/statics.md "Krylov steps").
// Eigen's preconditioner concept: compute / analyzePattern / factorize do nothing (the
// factor is made elsewhere, by SparseSolver::factorize), solve applies the factor's inverse.
#pragma once
#include <Eigen/Core>
#include <functional>

#include "statics/band_matrix.hpp"

namespace latmpm::statics {

class FactorPreconditioner {
 public:
  using Vector = Eigen::Matrix<Real, Eigen::Dynamic, 1>;
  using Apply = std::function<Vector(const Vector&)>;
  FactorPreconditioner() = default;
  void set(Apply apply) { apply_ = std::move(apply); }

  template <typename Matrix>
  FactorPreconditioner& analyzePattern(const Matrix&) { return *this; }
  template <typename Matrix>
  FactorPreconditioner& factorize(const Matrix&) { return *this; }
  template <typename Matrix>
  FactorPreconditioner& compute(const Matrix&) { return *this; }
  template <typename Rhs>
  Vector solve(const Rhs& b) const { return apply_(Vector(b)); }
  Eigen::ComputationInfo info() const { return apply_ ? Eigen::Success : Eigen::InvalidInput; }

 private:
  Apply apply_;
};

}  // namespace latmpm::statics
