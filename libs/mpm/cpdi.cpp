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

CpdiVertexStencils cpdi_vertex_stencils(const HexVertices& vertices, const std::array<Real, 8>& weight,
                                        const std::array<Vec3, 8>& gradient, Real h) {
  CpdiVertexStencils out;
  for (int a = 0; a < 8; ++a) {
    CpdiVertexStencil& v = out[size_t(a)];
    const Vec3 g = vertices[size_t(a)] / h;
    Vec3 fraction;
    for (int d = 0; d < 3; ++d) {
      v.cell[d] = int(std::floor(g[d]));
      fraction[d] = g[d] - v.cell[d];
    }
    for (int c = 0; c < 8; ++c)  // the eight tent functions N̄_I(x_α) of the vertex's cell
      v.tent[c] = ((c & 1) ? fraction.x() : 1 - fraction.x()) * ((c & 2) ? fraction.y() : 1 - fraction.y()) *
                  ((c & 4) ? fraction.z() : 1 - fraction.z());
    v.weight = weight[size_t(a)];
    v.gradient = gradient[size_t(a)];
  }
  return out;
}

namespace {

// Eq. 7 summed into the box of nodes the vertices' cells span.
CpdiStencil assemble(const CpdiVertexStencils& vertices, Real volume) {
  Eigen::Vector3i lo = Eigen::Vector3i::Constant(INT32_MAX), hi = Eigen::Vector3i::Constant(INT32_MIN);
  for (const CpdiVertexStencil& v : vertices) {
    lo = lo.cwiseMin(v.cell);
    hi = hi.cwiseMax(v.cell + Eigen::Vector3i::Ones());
  }
  CpdiStencil s;
  s.first_node = lo;
  s.node_count = hi - lo + Eigen::Vector3i::Ones();
  const size_t n = size_t(s.node_count.prod());
  s.weight.assign(n, 0);
  s.gradient.assign(n, Vec3::Zero());
  s.volume = volume;
  for (const CpdiVertexStencil& v : vertices)
    for (int c = 0; c < 8; ++c) {
      const Eigen::Vector3i local = v.node(c) - lo;
      const size_t e = size_t(local.x()) + size_t(s.node_count.x()) * (size_t(local.y()) + size_t(s.node_count.y()) * size_t(local.z()));
      s.weight[e] += v.weight * v.tent[c];
      s.gradient[e] += v.gradient * v.tent[c];
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
  return assemble(cpdi_vertex_stencils(vertices, weight, gradient, h), hex.volume);
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
  return assemble(cpdi_vertex_stencils(convected_vertices(position, F, domain.offsets), domain.weight_fraction, gradient, h),
                  jacobian * domain.volume);
}

}  // namespace latmpm::mpm
