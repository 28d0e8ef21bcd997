#include "geometry/unit_cell.hpp"

#include "geometry/strut_graph_builder.hpp"

namespace latmpm {

StrutGraph tile_unit_cell(const UnitCell& cell, int nx, int ny, int nz, double strut_radius) {
  // Merge nodes closer than a millionth of the shortest lattice vector: far below any
  // meaningful feature, far above the rounding of i·a1 + j·a2 + k·a3.
  const double tolerance = 1e-6 * cell.lattice_vectors.colwise().norm().minCoeff();
  StrutGraphBuilder builder(tolerance);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const Eigen::Vector3d shift = cell.lattice_vectors * Eigen::Vector3d(i, j, k);
        for (const auto& s : cell.struts) builder.strut(s[0] + shift, s[1] + shift, strut_radius);
      }
  StrutGraph graph;
  graph.name = cell.name;
  builder.move_into(graph);
  return graph;
}

}  // namespace latmpm
