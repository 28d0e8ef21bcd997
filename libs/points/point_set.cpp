#include "points/point_set.hpp"

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"

namespace latmpm {

int PointSet::body_index(const std::string& name) const {
  for (size_t i = 0; i < body_names.size(); ++i)
    if (body_names[i] == name) return static_cast<int>(i);
  return -1;
}

Eigen::Vector3d PointSet::domain_half_size(size_t p) const {
  Eigen::Vector3d half = half_size[p];
  for (int a = 0; a < 3; ++a)
    if (!(half[a] > 0)) half[a] = cell_size / (2 * std::max(ppc, 1));
  return half;
}

void PointSet::validate(const std::string& where) const {
  const size_t n = position.size();
  if (volume.size() != n) throw InputError(where, "/points/volume", "length differs from /points/position");
  if (body.size() != n) throw InputError(where, "/points/body", "length differs from /points/position");
  if (half_size.size() != n) throw InputError(where, "/points/half_size", "length differs from /points/position");
  if (!domain_vertices.empty() && domain_vertices.size() != n)
    throw InputError(where, "/points/domain_vertices", "length differs from /points/position");
  for (size_t i = 0; i < domain_vertices.size(); ++i) {
    for (const auto& v : domain_vertices[i])
      if (!v.allFinite()) throw InputError(where, "/points/domain_vertices", "point " + std::to_string(i) + " is not finite");
    if (!(hex_integrals(domain_vertices[i]).min_jacobian > 0))
      throw InputError(where, "/points/domain_vertices", "point " + std::to_string(i) + " has an inverted hexahedron");
  }
  for (const auto& [name, mask] : tags)
    if (mask.size() != n) throw InputError(where, "/points/tags/" + name, "length differs from /points/position");
  if (!(cell_size > 0) || !std::isfinite(cell_size)) throw InputError(where, "/points@cell_size", "must be positive");
  if (ppc < 1) throw InputError(where, "/points@ppc", "must be at least 1");
  for (size_t i = 0; i < n; ++i) {
    if (!position[i].allFinite())
      throw InputError(where, "/points/position", "point " + std::to_string(i) + " is not finite");
    if (!(volume[i] > 0) || !std::isfinite(volume[i]))
      throw InputError(where, "/points/volume", "point " + std::to_string(i) + " has a volume that is not positive");
    if (body[i] < 0 || size_t(body[i]) >= body_names.size())
      throw InputError(where, "/points/body", "point " + std::to_string(i) + " names a body that does not exist");
    if (!half_size[i].allFinite() || (half_size[i].array() < 0).any())
      throw InputError(where, "/points/half_size", "point " + std::to_string(i) + " has an invalid half-size");
  }
}

}  // namespace latmpm
