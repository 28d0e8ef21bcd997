#include "mpm/cpdi.hpp"

#include <cmath>

#include "core/errors.hpp"

namespace latmpm::mpm {

Eigen::Vector3i CpdiStencil::node(size_t n) const {
  const int i = int(n % size_t(node_count.x()));
  const int j = int((n / size_t(node_count.x())) % size_t(node_count.y()));
  const int k = int(n / (size_t(node_count.x()) * size_t(node_count.y())));
  return first_node + Eigen::Vector3i(i, j, k);
}

HexVertices convected_vertices(const Vec3& position, const Mat3& F, const HexVertices& reference_offsets) {
  HexVertices x;
  for (int a = 0; a < 8; ++a) x[a] = position + F * reference_offsets[a];
  return x;
}

namespace {

// Eq. 7 given the vertices and the per-vertex integrals already divided by the volume.
CpdiStencil assemble(const HexVertices& vertices, const std::array<Real, 8>& weight, const std::array<Vec3, 8>& gradient,
                     Real volume, Real h) {
  // The node box: every cell a vertex lies in.
  Eigen::Vector3i lo = Eigen::Vector3i::Constant(INT32_MAX), hi = Eigen::Vector3i::Constant(INT32_MIN);
  std::array<Eigen::Vector3i, 8> cell;
  std::array<Vec3, 8> fraction;
  for (int a = 0; a < 8; ++a) {
    const Vec3 g = vertices[a] / h;
    for (int d = 0; d < 3; ++d) {
      cell[a][d] = int(std::floor(g[d]));
      fraction[a][d] = g[d] - cell[a][d];
    }
    lo = lo.cwiseMin(cell[a]);
    hi = hi.cwiseMax(cell[a] + Eigen::Vector3i::Ones());
  }
  CpdiStencil s;
  s.first_node = lo;
  s.node_count = hi - lo + Eigen::Vector3i::Ones();
  const size_t n = size_t(s.node_count.prod());
  s.weight.assign(n, 0);
  s.gradient.assign(n, Vec3::Zero());
  s.volume = volume;
  for (int a = 0; a < 8; ++a) {
    // The eight tent functions N̄_I(x_α) of the vertex's cell.
    for (int c = 0; c < 8; ++c) {
      const int di = c & 1, dj = (c >> 1) & 1, dk = c >> 2;
      const Real tent = (di ? fraction[a].x() : 1 - fraction[a].x()) * (dj ? fraction[a].y() : 1 - fraction[a].y()) *
                        (dk ? fraction[a].z() : 1 - fraction[a].z());
      const Eigen::Vector3i local = cell[a] + Eigen::Vector3i(di, dj, dk) - lo;
      const size_t e = size_t(local.x()) + size_t(s.node_count.x()) * (size_t(local.y()) + size_t(s.node_count.y()) * size_t(local.z()));
      s.weight[e] += weight[a] * tent;
      s.gradient[e] += gradient[a] * tent;
    }
  }
  return s;
}

HexIntegrals checked_integrals(const HexVertices& vertices) {
  HexIntegrals hex = hex_integrals(vertices);
  if (!(hex.min_jacobian > 0)) throw NumericalError("CPDI domain inverted (det J <= 0 inside the hexahedron)");
  return hex;
}

}  // namespace

CpdiStencil cpdi_stencil(const HexVertices& vertices, Real h) {
  const HexIntegrals hex = checked_integrals(vertices);
  std::array<Real, 8> weight;
  std::array<Vec3, 8> gradient;
  for (int a = 0; a < 8; ++a) weight[a] = hex.vertex_weight[a] / hex.volume, gradient[a] = hex.vertex_gradient[a] / hex.volume;
  return assemble(vertices, weight, gradient, hex.volume, h);
}

CpdiDomain make_cpdi_domain(const HexVertices& reference_vertices) {
  const HexIntegrals hex = checked_integrals(reference_vertices);
  CpdiDomain d;
  d.volume = hex.volume;
  for (int a = 0; a < 8; ++a) {
    d.offsets[a] = reference_vertices[a] - hex.centroid;
    d.weight_fraction[a] = hex.vertex_weight[a] / hex.volume;
    d.gradient_per_volume[a] = hex.vertex_gradient[a] / hex.volume;
  }
  return d;
}

CpdiStencil cpdi_stencil(const CpdiDomain& domain, const Vec3& position, const Mat3& F, Real h) {
  const Real jacobian = F.determinant();
  if (!(jacobian > 0)) throw NumericalError("CPDI domain inverted (det F <= 0)");
  const Mat3 inverse_transpose = F.inverse().transpose();
  std::array<Vec3, 8> gradient;
  for (int a = 0; a < 8; ++a) gradient[a] = inverse_transpose * domain.gradient_per_volume[a];
  return assemble(convected_vertices(position, F, domain.offsets), domain.weight_fraction, gradient,
                  jacobian * domain.volume, h);
}

}  // namespace latmpm::mpm
