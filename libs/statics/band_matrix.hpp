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
