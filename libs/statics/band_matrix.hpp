// The stiffness matrix over the band's nodal displacements (3 unknowns per node), paper C
// Eq. (34): K_(ia)(jc) = Σ_p V_p Σ_bd ∇S_ip,b A_p,(ab)(cd) ∇S_jp,d, stored as a full
// symmetric Eigen sparse matrix whose pattern (every pair of nodes sharing a point) is
// built once, so that a solver's symbolic analysis is reused for every Newton step.
// Assembly runs over nodes: each node's column is summed from its own points, so threads
// never write the same entry and the sums have a fixed order (results do not depend on
// the number of threads).
#pragma once
#include <Eigen/SparseCore>
#include <functional>
#include <vector>

#include "statics/elastic_energy.hpp"
#include "statics/narrow_band.hpp"

namespace latmpm::statics {

using SparseMatrix = Eigen::SparseMatrix<Real, Eigen::ColMajor, int>;

class BandMatrix {
 public:
  explicit BandMatrix(const NarrowBand& band);

  // K from the points' weighted tangents: tangent(p, A) writes V_p ∂P/∂F at point p (N·m).
  void assemble(const std::function<void(size_t, Mat9&)>& tangent);
  // A scalar form over node pairs, one value per 3×3 block in the matrix's block order:
  // B_ij = Σ_p M_p,ij with row(p, e, out) writing row `e` (a band entry of point p) of point
  // p's stencil matrix, out[k] for the point's k-th entry. For quadratic forms acting alike
  // on each displacement component (the affine stabilisation), K = B ⊗ I₃.
  using StencilRow = std::function<void(size_t point, uint32_t entry, Real* row)>;
  std::vector<Real> assemble_blocks(const StencilRow& row) const;
  // K += B ⊗ I₃, and f += (B ⊗ I₃) u.
  void add_blocks(const std::vector<Real>& blocks);
  void multiply_blocks(const std::vector<Real>& blocks, const Eigen::Matrix<Real, Eigen::Dynamic, 1>& u,
                       Eigen::Matrix<Real, Eigen::Dynamic, 1>& f) const;

  SparseMatrix& matrix() { return matrix_; }
  const SparseMatrix& matrix() const { return matrix_; }

 private:
  const NarrowBand& band_;
  int span_ = 0;                    // 2N − 1 neighbour offsets per axis
  std::vector<int> slot_position_;  // per node span³ slots: neighbour position or −1
  std::vector<int> neighbor_offset_;  // per node: first neighbour in the node-major order
  SparseMatrix matrix_;
};

}  // namespace latmpm::statics
