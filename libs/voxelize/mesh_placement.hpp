// Placing an imported part: scale, rotations about the axes, optionally centring it in x and
// y and standing it on z = 0 (`place`), then translation, applied in that order, so a printed
// part can be stood on the compression axis (z) and on the lower platen. Parsers for the option
// texts live here too, so the tool stays thin and the parsing is tested.
#pragma once
#include <Eigen/Geometry>
#include <limits>
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
  bool place = false;  // after rotating: bounding box centred on x = y = 0, lowest point z = 0
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();  // m
  // Last: shift along z so that the lowest point is at this height (m), e.g. the top of
  // another part's points (a platen standing on the specimen). NaN: not used.
  double stand_on_z = std::numeric_limits<double>::quiet_NaN();

  // Scale, rotations and translation; `place` depends on the mesh (place_mesh applies it).
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
