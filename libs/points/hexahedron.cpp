#include "points/hexahedron.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace latmpm {

Eigen::Vector3d hex_reference_vertex(int alpha) {
  static const int sign[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                 {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  return {double(sign[alpha][0]), double(sign[alpha][1]), double(sign[alpha][2])};
}

namespace {

// Trilinear Q_α and ∂Q_α/∂ξ at the reference point xi.
void shape(const Eigen::Vector3d& xi, double q[8], Eigen::Vector3d dq[8]) {
  for (int a = 0; a < 8; ++a) {
    const Eigen::Vector3d s = hex_reference_vertex(a);
    const double fx = 1 + s.x() * xi.x(), fy = 1 + s.y() * xi.y(), fz = 1 + s.z() * xi.z();
    q[a] = fx * fy * fz / 8;
    dq[a] = Eigen::Vector3d(s.x() * fy * fz, fx * s.y() * fz, fx * fy * s.z()) / 8;
  }
}

Eigen::Matrix3d jacobian(const HexVertices& x, const Eigen::Vector3d dq[8]) {
  Eigen::Matrix3d J = Eigen::Matrix3d::Zero();  // J_ij = ∂x_i/∂ξ_j
  for (int a = 0; a < 8; ++a) J += x[a] * dq[a].transpose();
  return J;
}

// cof(J) = det J · J⁻ᵀ, computed without dividing (defined for degenerate J too).
Eigen::Matrix3d cofactor(const Eigen::Matrix3d& J) {
  Eigen::Matrix3d c;
  c.col(0) = J.col(1).cross(J.col(2));
  c.col(1) = J.col(2).cross(J.col(0));
  c.col(2) = J.col(0).cross(J.col(1));
  return c;  // c = det J · J⁻ᵀ: column j of J⁻ᵀ det J is the cross product of the other two
}

}  // namespace

HexIntegrals hex_integrals(const HexVertices& x) {
  HexIntegrals out;
  for (auto& v : out.vertex_gradient) v.setZero();
  const double g = 1 / std::sqrt(3.0);
  double q[8];
  Eigen::Vector3d dq[8];
  out.min_jacobian = INFINITY;
  for (int p = 0; p < 8; ++p) {
    const Eigen::Vector3d xi = g * hex_reference_vertex(p);
    shape(xi, q, dq);
    const Eigen::Matrix3d J = jacobian(x, dq);
    const Eigen::Matrix3d C = cofactor(J);
    const double det = J.determinant();
    out.min_jacobian = std::min(out.min_jacobian, det);
    out.volume += det;
    for (int a = 0; a < 8; ++a) {
      out.vertex_weight[a] += q[a] * det;
      out.vertex_gradient[a] += C * dq[a];  // grad Q_α det J = J⁻ᵀ ∂Q_α/∂ξ det J
      out.centroid += q[a] * det * x[a];
    }
  }
  // det J at the vertices bounds inversion better than the Gauss points alone.
  for (int a = 0; a < 8; ++a) {
    shape(hex_reference_vertex(a), q, dq);
    out.min_jacobian = std::min(out.min_jacobian, jacobian(x, dq).determinant());
  }
  if (out.volume != 0) out.centroid /= out.volume;
  return out;
}

}  // namespace latmpm
