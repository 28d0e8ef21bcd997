#include "imperfect/direction.hpp"

#include <cmath>
#include <sstream>

#include "core/errors.hpp"
#include "core/units.hpp"

namespace latmpm {

Eigen::Vector3d parse_horizontal_direction(const std::string& text, const std::string& where) {
  if (text == "x" || text == "+x") return {1, 0, 0};
  if (text == "-x") return {-1, 0, 0};
  if (text == "y" || text == "+y") return {0, 1, 0};
  if (text == "-y") return {0, -1, 0};
  if (text == "z" || text == "-z" || text == "+z")
    throw InputError(where, "", "'" + text + "' is the compression axis; give a horizontal direction (x, y, -x, -y or an angle such as 30deg)");
  Quantity q;
  try {
    q = parse_quantity(text, where, "");
  } catch (const InputError&) {
    throw InputError(where, "", "'" + text + "' is not a direction (x, y, -x, -y or an angle such as 30deg)");
  }
  if (q.dimension != dimension::angle)
    throw InputError(where, "", "'" + text + "' is not a direction (x, y, -x, -y or an angle such as 30deg)");
  return {std::cos(q.value), std::sin(q.value), 0.0};
}

std::string describe_direction(const Eigen::Vector3d& d) {
  if (d.isApprox(Eigen::Vector3d(1, 0, 0))) return "x";
  if (d.isApprox(Eigen::Vector3d(-1, 0, 0))) return "-x";
  if (d.isApprox(Eigen::Vector3d(0, 1, 0))) return "y";
  if (d.isApprox(Eigen::Vector3d(0, -1, 0))) return "-y";
  std::ostringstream os;
  os.precision(12);
  os << std::atan2(d.y(), d.x()) * 180.0 / M_PI << " deg";
  return os.str();
}

}  // namespace latmpm
