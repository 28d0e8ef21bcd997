#include "levelset/strut_surface.hpp"

#include <openvdb/tree/LeafManager.h>

#include <cmath>

#include "levelset/level_set_mesh.hpp"
#include "levelset/level_set_units.hpp"
#include "levelset/strut_level_set.hpp"

namespace latmpm {

TriangleMesh strut_graph_surface(const StrutGraph& graph, double voxel_size_m,
                                 const std::function<void(double)>& progress) {
  // Sampling the solid at (i − ½)·h equals sampling the solid shifted by +½h at i·h.
  const Eigen::Vector3d shift = Eigen::Vector3d::Constant(0.5 * voxel_size_m);
  StrutGraph shifted = graph;
  for (auto& n : shifted.nodes) n += shift;
  for (auto& p : shifted.plates) {
    p.min += shift;
    p.max += shift;
  }
  // volumeToMesh reads only the voxels next to the surface: a ±2-voxel band meshes exactly
  // as ±3 does, in a third less time.
  auto grid = strut_graph_level_set(shifted, voxel_size_m, 2.0, progress);
  const float nudge = float(1e-3 * voxel_size_m * grid_units_per_metre);
  openvdb::tree::LeafManager<openvdb::FloatTree> leaves(grid->tree());
  leaves.foreach([nudge](openvdb::FloatTree::LeafNodeType& leaf, size_t) {
    for (auto v = leaf.beginValueOn(); v; ++v)
      if (std::abs(*v) < nudge) v.setValue(*v < 0 ? -nudge : nudge);
  });
  TriangleMesh mesh = level_set_to_mesh(*grid);
  for (auto& v : mesh.vertices) v -= shift;
  return mesh;
}

}  // namespace latmpm
