#include "levelset/solid_measures.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/plates.hpp"
#include "levelset/level_set_mesh.hpp"
#include "levelset/level_set_units.hpp"

namespace latmpm {

SolidMeasures measure_solid(const StrutGraph& graph, const openvdb::FloatGrid& level_set) {
  SolidMeasures m;
  m.voxel_size = level_set.voxelSize()[0] / grid_units_per_metre;
  m.solid_volume = level_set_volume(level_set);
  for (const Plate& p : graph.plates) m.plate_volume += (p.max - p.min).prod();
  m.lattice_volume = m.solid_volume - m.plate_volume;
  if (!graph.struts.empty()) {
    const Eigen::AlignedBox3d footprint = solid_bounds(graph, true);
    double zmin = INFINITY, zmax = -INFINITY;
    for (const Strut& s : graph.struts)
      for (int32_t n : {s.a, s.b}) zmin = std::min(zmin, graph.nodes[n].z()), zmax = std::max(zmax, graph.nodes[n].z());
    if (graph.plates.empty()) zmin = footprint.min().z(), zmax = footprint.max().z();
    m.envelope_volume = footprint.sizes().x() * footprint.sizes().y() * (zmax - zmin);
    if (m.envelope_volume > 0) m.relative_density = m.lattice_volume / m.envelope_volume;
  }
  return m;
}

double expected_volume_error(double voxel_size, double strut_radius) {
  // 0.0044·(8h/r)² : the capsule measurement at r/8, scaled at second order.
  const double ratio = 8.0 * voxel_size / strut_radius;
  return 0.0044 * ratio * ratio;
}

}  // namespace latmpm
