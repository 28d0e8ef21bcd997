// A closed triangle mesh as an OpenVDB narrow-band level set (tools::meshToLevelSet):
// signed distance in grid units (mm, levelset/level_set_units.hpp), negative inside,
// interior resolved, cavities kept (inner shells facing inward), voxel (i, j, k) centred at
// (i, j, k)·voxel_size like strut_graph_level_set. The mesh must enclose a volume
// (check_mesh(...).encloses_volume()): an open mesh breaks the inside/outside classification.
#pragma once
#include <openvdb/openvdb.h>

#include <functional>

#include "mesh/triangle_mesh.hpp"

namespace latmpm {

// `progress(fraction_done)` is called now and then. Throws InputError("voxelize", ...) for a
// non-positive voxel size or band.
// `interior_half_width_voxels`: depth of the band inside (0: as outside), e.g. deeper to
// measure thin features (thin_features.hpp).
openvdb::FloatGrid::Ptr mesh_level_set(const TriangleMesh& mesh, double voxel_size_m,
                                       double half_width_voxels = 3.0,
                                       const std::function<void(double)>& progress = {},
                                       double interior_half_width_voxels = 0);

}  // namespace latmpm
