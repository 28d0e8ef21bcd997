#include "voxelize/mesh_placement.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/errors.hpp"
#include "core/units.hpp"

namespace latmpm {

Eigen::Affine3d Placement::transform() const {
  // Later operations multiply from the left: x' = T · R_n ⋯ R_1 · S · x.
  Eigen::Affine3d t = Eigen::Affine3d::Identity();
  t.prescale(scale);
  for (const AxisRotation& r : rotations)
    t.prerotate(Eigen::AngleAxisd(r.angle, Eigen::Vector3d::Unit(r.axis)));
  t.pretranslate(translation);
  return t;
}

bool Placement::is_identity() const {
  return scale == 1.0 && rotations.empty() && !place && translation.isZero(0.0) && std::isnan(stand_on_z);
}

AxisRotation parse_axis_rotation(const std::string& text, const std::string& where) {
  const size_t colon = text.find(':');
  const std::string axis = colon == std::string::npos ? "" : text.substr(0, colon);
  if (axis != "x" && axis != "y" && axis != "z")
    throw InputError(where, "rotation", "'" + text + "' is not AXIS:ANGLE with AXIS x, y or z (e.g. x:90deg)");
  AxisRotation r;
  r.axis = axis[0] - 'x';
  r.angle = parse_quantity(text.substr(colon + 1), dimension::angle, where, "rotation angle");
  return r;
}

Eigen::Vector3d parse_length_vector(const std::string& text, const std::string& where) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  for (std::string part; std::getline(in, part, ',');) parts.push_back(part);
  if (parts.size() != 3)
    throw InputError(where, "vector", "'" + text + "' is not three comma-separated lengths (e.g. 0mm,0mm,5mm)");
  Eigen::Vector3d v;
  for (int a = 0; a < 3; ++a)
    v[a] = parse_quantity(parts[a], dimension::length, where, std::string(1, char('x' + a)));
  return v;
}

void place_mesh(TriangleMesh& mesh, const Placement& placement) {
  if (!(placement.scale > 0) || !std::isfinite(placement.scale))
    throw InputError("--scale", "", "must be a positive factor");
  if (placement.is_identity()) return;
  Placement before_translation = placement;
  before_translation.translation.setZero();
  const Eigen::Affine3d t = before_translation.transform();
  for (auto& v : mesh.vertices) v = t * v;
  Eigen::Vector3d shift = placement.translation;
  if (placement.place && !mesh.vertices.empty()) {
    Eigen::AlignedBox3d box;
    for (const auto& v : mesh.vertices) box.extend(v);
    shift -= Eigen::Vector3d(box.center().x(), box.center().y(), box.min().z());
  }
  for (auto& v : mesh.vertices) v += shift;
  if (!std::isnan(placement.stand_on_z) && !mesh.vertices.empty()) {
    double lowest = INFINITY;
    for (const auto& v : mesh.vertices) lowest = std::min(lowest, v.z());
    for (auto& v : mesh.vertices) v.z() += placement.stand_on_z - lowest;
  }
}

}  // namespace latmpm
