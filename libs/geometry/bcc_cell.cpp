// Body-centred cubic cell: every cube corner joined to the cube centre.
#include <cmath>

#include "geometry/unit_cell.hpp"

namespace latmpm {

UnitCell bcc_cell(double strut_length) {
  const double a = 2.0 * strut_length / std::sqrt(3.0);  // half body diagonal = L
  UnitCell cell{"bcc", a * Eigen::Matrix3d::Identity(), {}};
  const Eigen::Vector3d centre(a / 2, a / 2, a / 2);
  for (int corner = 0; corner < 8; ++corner)
    cell.struts.push_back({Eigen::Vector3d(a * (corner & 1), a * ((corner >> 1) & 1),
                                           a * ((corner >> 2) & 1)),
                           centre});
  return cell;
}

}  // namespace latmpm
