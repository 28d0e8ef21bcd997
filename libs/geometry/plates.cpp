#include "geometry/plates.hpp"

#include <algorithm>
#include <cmath>

namespace latmpm {

Eigen::AlignedBox3d solid_bounds(const StrutGraph& graph, bool struts_only) {
  Eigen::AlignedBox3d box;  // empty
  for (const Strut& s : graph.struts) {
    const Eigen::Vector3d& p = graph.nodes[s.a];
    const Eigen::Vector3d& q = graph.nodes[s.b];
    Eigen::Vector3d reach = Eigen::Vector3d::Constant(s.radius);
    if (graph.strut_ends == StrutEnds::flat) {
      // A flat disc of radius r normal to u reaches r·sqrt(1 − u_i²) along axis i.
      const Eigen::Vector3d u = (q - p).normalized();
      for (int i = 0; i < 3; ++i) reach[i] = s.radius * std::sqrt(std::max(0.0, 1 - u[i] * u[i]));
    }
    box.extend(p.cwiseMin(q) - reach);
    box.extend(p.cwiseMax(q) + reach);
  }
  if (!struts_only)
    for (const Plate& plate : graph.plates) {
      box.extend(plate.min);
      box.extend(plate.max);
    }
  return box;
}

void centre_footprint(StrutGraph& graph) {
  const Eigen::AlignedBox3d box = solid_bounds(graph, true);
  Eigen::Vector3d shift = -box.center();
  shift.z() = 0;
  for (auto& n : graph.nodes) n += shift;
  for (auto& plate : graph.plates) {
    plate.min += shift;
    plate.max += shift;
  }
}

void add_plates(StrutGraph& graph, double thickness, double margin) {
  double zmin = INFINITY, zmax = -INFINITY;
  for (const auto& n : graph.nodes) zmin = std::min(zmin, n.z()), zmax = std::max(zmax, n.z());
  const Eigen::Vector3d shift(0, 0, thickness - zmin);
  for (auto& n : graph.nodes) n += shift;
  const Eigen::AlignedBox3d box = solid_bounds(graph, true);
  const double top = zmax - zmin + thickness;
  graph.plates.push_back({"bottom_plate", {box.min().x() - margin, box.min().y() - margin, 0.0},
                          {box.max().x() + margin, box.max().y() + margin, thickness}});
  graph.plates.push_back({"top_plate", {box.min().x() - margin, box.min().y() - margin, top},
                          {box.max().x() + margin, box.max().y() + margin, top + thickness}});
}

}  // namespace latmpm
