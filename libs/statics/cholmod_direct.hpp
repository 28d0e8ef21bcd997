// SuiteSparse CHOLMOD's supernodal Cholesky through its C interface, with the fill-reducing
// ordering computed on the node graph. The band matrix has 3 unknowns per node and full
// 3×3 blocks, so ordering the n-node graph and expanding each node to its 3 unknowns gives
// the same kind of ordering as ordering the 3n-unknown graph (METIS compresses identical
// rows to the same node graph anyway) at a ninth of the edges: on the paper-size T2P30
// lattice this cut the analysis from 7 s to ~1 s of CPU (docs/statics.md). Eigen's
// CholmodSupport offers no way to hand CHOLMOD a permutation, hence the C calls.
#pragma once
#include <memory>
#include <string>

#include "statics/band_matrix.hpp"

namespace latmpm::statics {

using Vector = Eigen::Matrix<Real, Eigen::Dynamic, 1>;

struct CholmodFigures {
  double factor_nonzeros = 0;  // nnz(L)
  double flops = 0;            // of one numeric factorisation
  bool node_ordering = false;  // ordered on the node graph (3×3 blocks found)
  std::string ordering;        // "amd", "metis", "nesdis", ...
};

class CholmodDirect {
 public:
  CholmodDirect();
  ~CholmodDirect();
  CholmodDirect(const CholmodDirect&) = delete;
  CholmodDirect& operator=(const CholmodDirect&) = delete;

  // Orders and analyses K's pattern (lower triangle used): once per pattern.
  void analyse(const SparseMatrix& K);
  // Numeric factorisation; false when K is not positive definite.
  bool factorize(const SparseMatrix& K);
  Vector solve(const Vector& b);
  bool analysed() const;
  const CholmodFigures& figures() const { return figures_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  CholmodFigures figures_;
};

}  // namespace latmpm::statics
