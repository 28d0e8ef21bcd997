#include "statics/affine_stabilisation.hpp"

#include <Eigen/Core>

namespace latmpm::statics {

std::vector<Real> affine_stabilisation_blocks(const BandMatrix& matrix, const NarrowBand& band,
                                              const std::vector<Real>& coefficient) {
  using Vec4 = Eigen::Matrix<Real, 4, 1>;
  using Mat4 = Eigen::Matrix<Real, 4, 4>;
  // Point p's stencil matrix M = Cᵀ W C with W = diag(S_kp) and C_kj = δ_kj − ψ_k·φ_j,
  // φ_j = (S_jp, ∇S_jp), ψ_k = (1, X_k − X_p): r = C u is the departure from the affine field.
  //   M_ij = w_i δ_ij − w_j ψ_j·φ_i − w_i ψ_i·φ_j + φ_iᵀ Q φ_j,   Q = Σ_k w_k ψ_k ψ_kᵀ.
  // Positions are taken relative to the row's own node (grid offsets × h) against round-off.
  return matrix.assemble_blocks([&](size_t p, uint32_t own, Real* row) {
    const uint32_t first = band.point_offset[p], last = band.point_offset[p + 1];
    const Eigen::Vector3i& origin = band.node[band.entry_node[own]];
    auto position = [&](uint32_t e) -> Vec3 {
      return band.cell_size * (band.node[band.entry_node[e]] - origin).cast<Real>();
    };
    Vec3 Xp = Vec3::Zero();
    for (uint32_t e = first; e < last; ++e) Xp += band.entry_weight[e] * position(e);
    auto psi = [&](uint32_t e) {
      Vec4 v;
      v << 1, position(e) - Xp;
      return v;
    };
    auto phi = [&](uint32_t e) {
      Vec4 v;
      v << band.entry_weight[e], band.entry_gradient[e];
      return v;
    };
    const Real w = Real(1) / Real(last - first);  // every stencil node alike
    Mat4 Q = Mat4::Zero();
    for (uint32_t e = first; e < last; ++e) {
      const Vec4 s = psi(e);
      Q += w * s * s.transpose();
    }
    const Real c = coefficient[p], wi = w;
    const Vec4 phi_i = phi(own), psi_i = psi(own), Q_phi_i = Q * phi_i;
    for (uint32_t e = first; e < last; ++e) {
      const Vec4 phi_j = phi(e);
      Real m = -w * psi(e).dot(phi_i) - wi * psi_i.dot(phi_j) + Q_phi_i.dot(phi_j);
      if (e == own) m += wi;
      row[e - first] = c * m;
    }
  });
}

}  // namespace latmpm::statics
