// Dirichlet conditions of the static solve (paper C Eq. 27): prescribed displacement
// components of band nodes, imposed by modifying the matrix and right-hand side (paper C
// Sec. 3.3: equivalent to eliminating the Lagrange multipliers of the KKT system).
#pragma once
#include <vector>

#include "statics/static_problem.hpp"

namespace latmpm::statics {

struct Dirichlet {
  std::vector<char> fixed;  // per unknown (3 per band node): 1 where prescribed
  Vector value;             // per unknown, m: the prescribed displacement where fixed

  explicit Dirichlet(size_t dofs = 0) : fixed(dofs, 0), value(Vector::Zero(Eigen::Index(dofs))) {}
  // Prescribes all three components of node n.
  void prescribe(size_t node, const Vec3& displacement);
  size_t count() const;
};

// Band nodes that the stencils of the given points reach (a rigid body's points: the nodes
// it drives, as in the explicit solver's grid update), sorted.
std::vector<size_t> nodes_reached_by(const NarrowBand& band, const std::vector<Vec3>& X,
                                     const std::vector<Vec3>& half_size);

// Makes rows and columns of the prescribed unknowns zero with `diagonal` on the diagonal
// (keeps the pattern: factorisations reuse their analysis).
void constrain_rows_and_columns(SparseMatrix& K, const std::vector<char>& fixed, Real diagonal);

// A diagonal value of the same order as K's, so constraints do not spoil its conditioning.
Real mean_diagonal(const SparseMatrix& K);

}  // namespace latmpm::statics
