// One small interface over the sparse symmetric solvers of the static solve: Eigen's
// SimplicialLDLT (direct, in-tree), Eigen's ConjugateGradient with an incomplete Cholesky
// preconditioner (iterative, low memory) and SuiteSparse CHOLMOD's supernodal Cholesky
// (direct; cholmod_direct.hpp) and CG preconditioned by hypre's BoomerAMG (iterative;
// hypre_amg.hpp). "auto" takes CHOLMOD unless its analysed factor would fill more than
// half of the machine's memory, then the AMG: on the lattices CHOLMOD is the faster of the
// two up to the paper size (docs/statics.md), the AMG's merit is a memory that grows only
// linearly. The pattern is analysed once and each Newton step only refactorises (or
// rebuilds the AMG hierarchy).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "statics/band_matrix.hpp"
#include "statics/phase_time.hpp"
#include "statics/static_problem.hpp"
#include "statics/static_settings.hpp"  // LinearSolverKind

namespace latmpm::statics {


// Where a solver's time went (the run log's profile line).
struct SolverTimes {
  PhaseTime analyse;    // ordering and symbolic analysis (once per pattern; LDLT, CHOLMOD)
  PhaseTime factorise;  // numeric factorisations, or the AMG / incomplete-Cholesky set-ups
  PhaseTime solve;      // triangular solves or iterations
  PhaseTime krylov;     // CG preconditioned by an earlier factor (solve_preconditioned)
};

struct LinearSolveStats {
  int iterations = 0;             // CG / PCG iterations (1 for a direct solve)
  Real relative_residual = 0;     // ‖K x − b‖ / ‖b‖ of the last solve
};

class SparseSolver {
 public:
  // tolerance and max_iterations: of CG and of the AMG's PCG (‖K x − b‖ ≤ tolerance ‖b‖).
  explicit SparseSolver(LinearSolverKind kind, Real tolerance = 1e-10, int max_iterations = 20000);
  // "auto"'s budget for CHOLMOD's factor, bytes (default: half the physical memory).
  void set_factor_memory_budget(double bytes) { factor_memory_budget_ = bytes; }
  ~SparseSolver();
  SparseSolver(const SparseSolver&) = delete;
  SparseSolver& operator=(const SparseSolver&) = delete;

  LinearSolverKind kind() const { return kind_; }
  // Whether factorize() tells a positive definite matrix from one that is not (LDLT,
  // CHOLMOD, or "auto" once it chose CHOLMOD): such a solver can also do stability checks.
  bool is_direct() const { return used_ == LinearSolverKind::ldlt || used_ == LinearSolverKind::cholmod; }
  const SolverTimes& times() const { return times_; }
  // Node positions (m) for the AMG's rigid-body modes (node n: unknowns 3n..3n+2).
  void set_node_positions(std::vector<Vec3> positions);
  // The solver's name and, once used, CHOLMOD's ordering, nnz(L) and flop count or the
  // AMG's levels and operator complexity.
  std::string describe() const;
  // Factorises K (the pattern is analysed on the first call; "auto" picks its solver
  // then, from CHOLMOD's analysis and the memory budget). Returns false when the direct solvers find K not positive definite; CG and AMG
  // only build their preconditioner.
  bool factorize(const SparseMatrix& K);
  // Solves K x = b with the last factorisation; throws NumericalError when CG does not
  // reach its tolerance.
  Vector solve(const Vector& b, LinearSolveStats& stats);
  // Whether the last factorize() of a direct solver succeeded: its factor (of a positive
  // definite matrix) can precondition solve_preconditioned.
  bool has_factor() const { return factor_valid_; }
  // Solves K x = b by conjugate gradients preconditioned with the last factor (of an
  // earlier, nearby matrix; factor_preconditioner.hpp) to ‖K x − b‖ ≤ tolerance ‖b‖. False
  // (x unusable) when there is no factor or CG does not get there in max_iterations.
  bool solve_preconditioned(const SparseMatrix& K, const Vector& b, Real tolerance, int max_iterations, Vector& x,
                            LinearSolveStats& stats);

 private:
  struct Impl;
  bool factorize_matrix(const SparseMatrix& K);
  LinearSolverKind kind_;
  LinearSolverKind used_;  // kind_, or what "auto" chose
  Real iterative_tolerance_;
  int iterative_max_iterations_;
  double factor_memory_budget_;
  SolverTimes times_;
  bool factor_valid_ = false;
  std::unique_ptr<Impl> impl_;
};

}  // namespace latmpm::statics
