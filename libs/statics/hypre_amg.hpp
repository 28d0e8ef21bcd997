// Conjugate gradients preconditioned by hypre's BoomerAMG (Debian's libhypre-dev): the
// iterative alternative to CHOLMOD for large band matrices, whose factorisation costs
// grow as nnz(L) (paper-size T2P30: 2.7e8 entries, 4e11 flops; docs/statics.md). The AMG is
// set up for linear elasticity as hypre's documentation advises for systems of PDEs: three
// functions per node (unknowns 3n, 3n+1, 3n+2 of node n), nodal coarsening on the row-sum
// norm of the 3×3 blocks, and the rigid-body rotations of the nodes as interpolation
// vectors (the GM-2 variant of Baker, Kolev and Yang, "Improving algebraic multigrid
// interpolation operators for linear elasticity problems", Numer. Linear Algebra Appl. 17,
// 2010), the near-null space that plain systems AMG misses.
//
// hypre is an MPI library: the first HypreAmg initialises MPI (singleton, one process) and
// hypre unless the program already did, and both are finalised at exit. Everything runs on
// MPI_COMM_SELF.
#pragma once
#include <memory>
#include <vector>

#include "statics/band_matrix.hpp"

namespace latmpm::statics {

using Vector = Eigen::Matrix<Real, Eigen::Dynamic, 1>;

struct AmgFigures {
  int levels = 0;
  double operator_complexity = 0;  // Σ nnz(A_level) / nnz(A)
};

class HypreAmg {
 public:
  // PCG stops at ‖K x − b‖ ≤ tolerance ‖b‖ or after max_iterations.
  HypreAmg(Real tolerance, int max_iterations);
  ~HypreAmg();
  HypreAmg(const HypreAmg&) = delete;
  HypreAmg& operator=(const HypreAmg&) = delete;

  // Node positions (m) for the rigid-body rotations, node n owning unknowns 3n..3n+2; without
  // them the AMG coarsens by nodes but interpolates translations only.
  void set_node_positions(std::vector<Vec3> positions) { positions_ = std::move(positions); }
  // Copies K (full symmetric storage) into hypre and builds the AMG hierarchy.
  void setup(const SparseMatrix& K);
  // PCG from x = 0; returns x and sets the iterations and hypre's final relative residual.
  // Throws NumericalError when PCG stops above its tolerance.
  Vector solve(const Vector& b, int& iterations, Real& relative_residual);
  const AmgFigures& figures() const { return figures_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::vector<Vec3> positions_;
  AmgFigures figures_;
  Real tolerance_;
  int max_iterations_;
};

}  // namespace latmpm::statics
