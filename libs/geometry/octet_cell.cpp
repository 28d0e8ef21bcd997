// Octet-truss cell (Deshpande, Fleck & Ashby 2001): the face-centred cubic points of one cube
// (8 corners, 6 face centres), every pair at the nearest-neighbour distance a/√2 joined.
// That gives 36 struts per cube: 24 on its faces (shared with neighbours, merged when tiled)
// and 12 inside forming the octahedron.
#include <cmath>

#include "geometry/unit_cell.hpp"

namespace latmpm {

UnitCell octet_cell(double strut_length) {
  const double a = std::sqrt(2.0) * strut_length;
  UnitCell cell{"octet", a * Eigen::Matrix3d::Identity(), {}};
  std::vector<Eigen::Vector3d> points;
  for (int corner = 0; corner < 8; ++corner)
    points.emplace_back(a * (corner & 1), a * ((corner >> 1) & 1), a * ((corner >> 2) & 1));
  for (int axis = 0; axis < 3; ++axis)
    for (double side : {0.0, a}) {
      Eigen::Vector3d face_centre = Eigen::Vector3d::Constant(a / 2);
      face_centre[axis] = side;
      points.push_back(face_centre);
    }
  for (size_t i = 0; i < points.size(); ++i)
    for (size_t j = i + 1; j < points.size(); ++j)
      if (std::abs((points[i] - points[j]).norm() - strut_length) < 1e-9 * strut_length)
        cell.struts.push_back({points[i], points[j]});
  return cell;
}

}  // namespace latmpm
