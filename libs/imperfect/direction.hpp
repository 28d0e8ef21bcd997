// Horizontal directions for the lateral perturbations (docs/imperfections.md, "Directions").
//   "x", "y", "-x", "-y"   the axes
//   "30deg", "-0.5rad"     an angle in the horizontal plane, measured from +x towards +y
// The compression axis is z, so every direction returned here has a zero z component.
#pragma once
#include <Eigen/Core>
#include <string>

namespace latmpm {

// A unit vector (cos θ, sin θ, 0). Throws InputError naming `where` for anything else.
Eigen::Vector3d parse_horizontal_direction(const std::string& text, const std::string& where);

// "x", "-y" or "30 deg": the shortest text that parses back to the same direction.
std::string describe_direction(const Eigen::Vector3d& direction);

}  // namespace latmpm
