// How thin are a part's walls and struts? Measured on its level set, from the medial surface:
// an interior voxel where φ has a V-shaped minimum across some axis (both neighbours two
// voxels away higher by at least half a voxel) lies on the mid-surface of a wall or the axis
// of a strut, and the V's apex, fitted through the voxel and its two neighbours, is minus
// half the local thickness there. Convex edges and corners of thick parts are not ridges (φ
// is flat on one side along every axis), so only walls and struts are measured.
// Below two cells across, the volume error and the bending stiffness error both grow
// (docs/voxelize.md): the voxelizer warns and says by how much.
#pragma once
#include <openvdb/openvdb.h>

#include <cstddef>
#include <string>

namespace latmpm {

struct ThinFeatures {
  double limit = 0;          // m: thickness below which a feature counts as thin
  size_t ridge_voxels = 0;   // medial voxels measured (within the level set's interior band)
  size_t thin_voxels = 0;    // of which thinner than `limit`
  double thinnest = 0;       // m: the thinnest feature (tenth percentile of the thin ridge), 0 if none
  bool any() const { return thin_voxels > 0; }
};

// `level_set` in grid units (levelset/level_set_units.hpp) with its interior band at least
// limit/2 + 2 voxels deep (thicker features are then not ridges of the band and count as
// thick). `limit` in metres.
ThinFeatures find_thin_features(const openvdb::FloatGrid& level_set, double limit);

// "thinnest wall or strut 0.45 mm, 0.75 cells across (two cells: 1.2 mm, 0.75 mm more);
//  12 % of the measured mid-surface is thinner than two cells"
std::string describe(const ThinFeatures& thin, double cell_size);

}  // namespace latmpm
