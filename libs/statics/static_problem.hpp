// The discrete elastostatic problem of paper C Eq. (28) on the narrow band: minimise
//   E(u) = Σ_p V_p ψ_p(F_p(u)) − f·u,   F_p = I + Σ_i u_i ⊗ ∇S_ip  (Eq. 32)
// over the nodal displacements u (3 per band node, m) with dead nodal loads f (N). This
// file evaluates E, its gradient (Eq. 33: internal minus external force) and its Hessian
// (Eq. 34), projected per point or not; the solvers live in projected_newton.hpp.
#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "statics/band_matrix.hpp"
#include "statics/elastic_energy.hpp"
#include "statics/narrow_band.hpp"
#include "statics/phase_time.hpp"

namespace latmpm::statics {

using Vector = Eigen::Matrix<Real, Eigen::Dynamic, 1>;

class StaticProblem {
 public:
  // Points with reference volumes V_p (m³), each with the energy energies[material[p]].
  StaticProblem(NarrowBand band, std::vector<Real> volume, std::vector<uint16_t> material,
                std::vector<ElasticEnergy> energies);
  // The band matrix refers to the band: neither copied nor moved (C++17 returns it in place).
  StaticProblem(const StaticProblem&) = delete;
  StaticProblem& operator=(const StaticProblem&) = delete;

  const NarrowBand& band() const { return band_; }
  size_t dof_count() const { return 3 * band_.node_count(); }
  size_t point_count() const { return volume_.size(); }

  // Dead loads: a force on each point (N), spread to the nodes with the weights S_ip.
  void set_point_forces(const std::vector<Vec3>& force);
  const Vector& external_force() const { return external_; }

  // Adds the affine stabilisation (affine_stabilisation.hpp) with c_p = β μ_p V_p / h² to
  // the energy, forces and Hessian; β = 0 removes it.
  void set_stabilisation(Real beta);
  Real stabilisation() const { return stabilisation_; }

  // Whether every energy is quadratic (linear elastic): constant Hessian, no inversion.
  bool is_quadratic() const;

  Mat3 deformation_gradient(size_t p, const Vector& u) const;
  // Point p's first Piola–Kirchhoff stress at F (Pa).
  Mat3 first_piola(size_t p, const Mat3& F) const { return energies_[material_[p]].first_piola(F); }
  std::vector<Mat3> deformation_gradients(const Vector& u) const;
  // Smallest det F_p, and whether every point's det F_p > 0.
  Real min_jacobian(const Vector& u) const;

  // E(u), J. Requires det F_p > 0 at every point for neo-Hookean energies.
  Real energy(const Vector& u) const;
  // Internal nodal forces ∂/∂u Σ V_p ψ_p (N); the gradient of E is this minus f.
  Vector internal_force(const Vector& u) const;
  // The Hessian of E into the band matrix: per point ∂P/∂F projected to semidefinite
  // (projected Newton) or not (the true tangent, for stability checks).
  void assemble_hessian(const Vector& u, bool projected);
  SparseMatrix& hessian() { return matrix_.matrix(); }
  // Time spent in assemble_hessian (the run log's profile line).
  const PhaseTime& assembly_time() const { return assembly_time_; }

 private:
  template <class F>
  void for_points(F&& f) const;

  NarrowBand band_;
  std::vector<Real> volume_;
  std::vector<uint16_t> material_;
  std::vector<ElasticEnergy> energies_;
  Vector external_;
  BandMatrix matrix_;
  Real stabilisation_ = 0;
  std::vector<Real> stabilisation_blocks_;  // scalar Hessian of E_s per node pair (empty: none)
  std::vector<Mat9> point_tangent_;  // V_p ∂P/∂F of the last assembly (non-quadratic energies)
  PhaseTime assembly_time_;
};

}  // namespace latmpm::statics
