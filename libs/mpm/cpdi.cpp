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

CpdiStencil cpdi_stencil(const HexVertices& vertices, Real h) {
  const HexIntegrals hex = hex_integrals(vertices);
  if (!(hex.min_jacobian > 0)) throw NumericalError("CPDI domain inverted (det J <= 0 inside the hexahedron)");
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
  s.volume = hex.volume;
  const Real inv_v = 1 / hex.volume;
  for (int a = 0; a < 8; ++a) {
    // The eight tent functions N̄_I(x_α) of the vertex's cell.
    for (int c = 0; c < 8; ++c) {
      const int di = c & 1, dj = (c >> 1) & 1, dk = c >> 2;
      const Real tent = (di ? fraction[a].x() : 1 - fraction[a].x()) * (dj ? fraction[a].y() : 1 - fraction[a].y()) *
                        (dk ? fraction[a].z() : 1 - fraction[a].z());
      const Eigen::Vector3i local = cell[a] + Eigen::Vector3i(di, dj, dk) - lo;
      const size_t e = size_t(local.x()) + size_t(s.node_count.x()) * (size_t(local.y()) + size_t(s.node_count.y()) * size_t(local.z()));
      s.weight[e] += inv_v * hex.vertex_weight[a] * tent;
      s.gradient[e] += inv_v * hex.vertex_gradient[a] * tent;
    }
  }
  return s;
}

}  // namespace latmpm::mpm
