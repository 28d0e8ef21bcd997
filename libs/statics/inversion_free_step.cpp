#include "statics/inversion_free_step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <unsupported/Eigen/Polynomials>

namespace latmpm::statics {

namespace {
// adj(A) = det(A) A⁻¹, written out (defined for singular A too).
Mat3 adjugate(const Mat3& A) {
  Mat3 c;
  c(0, 0) = A(1, 1) * A(2, 2) - A(1, 2) * A(2, 1);
  c(0, 1) = A(0, 2) * A(2, 1) - A(0, 1) * A(2, 2);
  c(0, 2) = A(0, 1) * A(1, 2) - A(0, 2) * A(1, 1);
  c(1, 0) = A(1, 2) * A(2, 0) - A(1, 0) * A(2, 2);
  c(1, 1) = A(0, 0) * A(2, 2) - A(0, 2) * A(2, 0);
  c(1, 2) = A(0, 2) * A(1, 0) - A(0, 0) * A(1, 2);
  c(2, 0) = A(1, 0) * A(2, 1) - A(1, 1) * A(2, 0);
  c(2, 1) = A(0, 1) * A(2, 0) - A(0, 0) * A(2, 1);
  c(2, 2) = A(0, 0) * A(1, 1) - A(0, 1) * A(1, 0);
  return c;
}
}  // namespace

Real inversion_free_step(const Mat3& F, const Mat3& D, Real margin) {
  const Real det_f = F.determinant();
  // Coefficients of det(F + αD) − margin·det F in increasing degree.
  Eigen::Matrix<Real, 4, 1> c((1 - margin) * det_f, (adjugate(F) * D).trace(),
                              (F * adjugate(D)).trace(), D.determinant());
  // Drop leading terms too small to matter for α up to ~1e3 (the cubic is then lower degree).
  const Real scale = c.cwiseAbs().maxCoeff();
  int degree = 3;
  while (degree > 0 && std::abs(c[degree]) <= 1e-14 * scale) --degree;
  if (degree == 0) return std::numeric_limits<Real>::infinity();
  Real best = std::numeric_limits<Real>::infinity();
  if (degree == 1) {
    const Real root = -c[0] / c[1];
    return root > 0 ? root : best;
  }
  Eigen::PolynomialSolver<Real, Eigen::Dynamic> solver;
  solver.compute(Eigen::Matrix<Real, Eigen::Dynamic, 1>(c.head(degree + 1)));
  for (const auto& root : solver.roots())
    if (std::abs(root.imag()) <= 1e-10 * std::max(Real(1), std::abs(root.real())) && root.real() > 0)
      best = std::min(best, root.real());
  return best;
}

Real inversion_free_step(const std::vector<Mat3>& F, const std::vector<Mat3>& D, Real margin) {
  Real best = std::numeric_limits<Real>::infinity();
  for (size_t p = 0; p < F.size(); ++p) best = std::min(best, inversion_free_step(F[p], D[p], margin));
  return best;
}

}  // namespace latmpm::statics
