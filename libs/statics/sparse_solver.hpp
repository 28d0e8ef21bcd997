// One small interface over the sparse symmetric solvers of the static solve: Eigen's
// SimplicialLDLT (direct, in-tree), Eigen's ConjugateGradient with an incomplete Cholesky
// preconditioner (iterative, low memory) and SuiteSparse CHOLMOD's supernodal Cholesky
// (direct, for large problems; cholmod_direct.hpp). The pattern is analysed once
// and each Newton step only refactorises.
#pragma once
#include <memory>
#include <string>

#include "statics/band_matrix.hpp"
#include "statics/static_problem.hpp"
#include "statics/static_settings.hpp"  // LinearSolverKind

namespace latmpm::statics {


struct LinearSolveStats {
  int iterations = 0;             // CG iterations (1 for a direct solve)
  Real relative_residual = 0;     // ‖K x − b‖ / ‖b‖ of the last solve
};

class SparseSolver {
 public:
  explicit SparseSolver(LinearSolverKind kind, Real cg_tolerance = 1e-10, int cg_max_iterations = 20000);
  ~SparseSolver();
  SparseSolver(const SparseSolver&) = delete;
  SparseSolver& operator=(const SparseSolver&) = delete;

  LinearSolverKind kind() const { return kind_; }
  // The solver's name and, for CHOLMOD once analysed, its ordering, nnz(L) and flop count.
  std::string describe() const;
  // Factorises K (the pattern is analysed on the first call). Returns false when the direct
  // solvers find K not positive definite; CG only checks that its preconditioner exists.
  bool factorize(const SparseMatrix& K);
  // Solves K x = b with the last factorisation; throws NumericalError when CG does not
  // reach its tolerance.
  Vector solve(const Vector& b, LinearSolveStats& stats);

 private:
  struct Impl;
  LinearSolverKind kind_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace latmpm::statics
