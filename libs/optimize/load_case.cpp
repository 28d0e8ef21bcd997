#include "optimize/load_case.hpp"

namespace latmpm::optimize {

std::vector<std::vector<size_t>> loaded_points(const DesignGrid& grid, const LoadCase& load_case) {
  std::vector<std::vector<size_t>> points(load_case.loads.size());
  for (size_t q = 0; q < grid.point_count(); ++q) {
    const Vec3 x = grid.position(q);
    for (size_t l = 0; l < load_case.loads.size(); ++l)
      if (load_case.loads[l].box.contains(x)) points[l].push_back(q);
  }
  return points;
}

}  // namespace latmpm::optimize
