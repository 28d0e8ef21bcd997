// Small synthetic inputs for the imperfection tests, built here so the tests do not depend
// on the lattice generator or the voxelizer: a printed "lattice" block between two bases
// (points on the voxelizer's grid rule) and a solid column.
#pragma once
#include <cmath>

#include "geometry/strut_graph.hpp"
#include "points/point_set.hpp"

namespace latmpm::test {

// Points at (i + 1/2)·spacing filling z ∈ [0, 54.4 mm] over a 6.4 × 3.2 mm footprint:
// bottom_plate z < 3.2 mm, lattice (five 9.6 mm layers) up to 51.2 mm, top_plate above.
inline PointSet printed_block(bool with_parameters = true) {
  const double s = 0.32e-3;
  PointSet p;
  p.cell_size = 2 * s;
  p.ppc = 2;
  p.body_names = {"bottom_plate", "lattice", "top_plate"};
  for (int k = 0; k < 170; ++k)
    for (int j = 0; j < 10; ++j)
      for (int i = 0; i < 20; ++i) {
        const Eigen::Vector3d x((i + 0.5) * s, (j + 0.5) * s, (k + 0.5) * s);
        p.position.push_back(x);
        p.volume.push_back(s * s * s);
        p.half_size.push_back(Eigen::Vector3d::Constant(s / 2));
        p.body.push_back(k < 10 ? 0 : k < 160 ? 1 : 2);
        p.tags["record"].push_back(k == 0);
      }
  if (with_parameters)
    p.parameters = {{"layer_height", "9.6 mm"}, {"lattice_zmin", "3.2 mm"}, {"lattice_zmax", "51.2 mm"}, {"cells", "1x1x5"}};
  return p;
}

// A solid cylinder of radius r along z from 0 to `length`, points `spacing` apart.
inline PointSet solid_column(double length = 16e-3, double radius = 0.8e-3, double spacing = 0.2e-3) {
  PointSet p;
  p.cell_size = 2 * spacing;
  p.ppc = 2;
  p.body_names = {"column"};
  const int n = static_cast<int>(std::ceil(radius / spacing));
  const int layers = static_cast<int>(std::lround(length / spacing));
  for (int k = 0; k < layers; ++k)
    for (int j = -n; j < n; ++j)
      for (int i = -n; i < n; ++i) {
        const Eigen::Vector3d x((i + 0.5) * spacing, (j + 0.5) * spacing, (k + 0.5) * spacing);
        if (x.head<2>().norm() > radius) continue;
        p.position.push_back(x);
        p.volume.push_back(spacing * spacing * spacing);
        p.half_size.push_back(Eigen::Vector3d::Constant(spacing / 2));
        p.body.push_back(0);
      }
  return p;
}

}  // namespace latmpm::test
