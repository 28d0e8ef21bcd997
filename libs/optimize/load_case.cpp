#include "optimize/load_case.hpp"

#include <algorithm>

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

std::vector<SymmetryPlane> symmetry_planes(const DesignGrid& grid, const LoadCase& load_case) {
  std::vector<SymmetryPlane> planes;
  const Vec3 extent = grid.extent();
  for (const Support& s : load_case.supports) {
    if (std::count(s.held.begin(), s.held.end(), true) != 1) continue;
    const int a = int(std::find(s.held.begin(), s.held.end(), true) - s.held.begin());
    if (grid.planar && a == 2) continue;  // a planar design's z is held everywhere anyway
    // Only nodes of one face: the box reaches no node plane inside the domain.
    const Real h = grid.cell_size, tol = 1e-9 * h;
    if (s.box.hi[a] < h - tol) planes.push_back({a, false});
    else if (s.box.lo[a] > extent[a] - h + tol) planes.push_back({a, true});
  }
  return planes;
}

}  // namespace latmpm::optimize
