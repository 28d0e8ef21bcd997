#include "statics/spd_projection.hpp"

#include <Eigen/Eigenvalues>

namespace latmpm::statics {

Mat9 project_to_semidefinite(const Mat9& A) {
  const Mat9 sym = Real(0.5) * (A + A.transpose());
  Eigen::SelfAdjointEigenSolver<Mat9> eigen(sym);
  const auto& values = eigen.eigenvalues();
  if (values.minCoeff() >= 0) return sym;
  const auto& vectors = eigen.eigenvectors();
  return vectors * values.cwiseMax(Real(0)).asDiagonal() * vectors.transpose();
}

}  // namespace latmpm::statics
