// Placing an imported part: scale, rotations about the axes, translation, applied in that
// order, so a printed part can be stood on the compression axis (z). Parsers for the option
// texts live here too, so the tool stays thin and the parsing is tested.
#pragma once
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "mesh/triangle_mesh.hpp"

namespace latmpm {

struct AxisRotation {
  int axis = 2;      // 0 x, 1 y, 2 z
  double angle = 0;  // rad, right-handed about the axis
};

struct Placement {
  double scale = 1.0;                  // uniform factor, > 0 (a mirror would turn the part inside out)
  std::vector<AxisRotation> rotations;  // applied in order
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();  // m

  Eigen::Affine3d transform() const;
  bool is_identity() const;
};

// "x:90deg", "z:-30deg" → AxisRotation. Throws InputError(where, "rotation", ...).
AxisRotation parse_axis_rotation(const std::string& text, const std::string& where);
// "0mm,0mm,5mm" (three lengths with units, comma-separated) → metres.
Eigen::Vector3d parse_length_vector(const std::string& text, const std::string& where);

// Applies the placement to every vertex.
void place_mesh(TriangleMesh& mesh, const Placement& placement);

}  // namespace latmpm
