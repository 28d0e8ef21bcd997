// The world unit of latmpm's OpenVDB grids: millimetres, not metres.
//
// OpenVDB refuses a transform whose voxel volume is below 3e-15 world units³ (ScaleMap,
// "Non-zero scale values required"): in metres that is any voxel under 14 µm, so cells of
// 0.05 mm, or micro-lattices (struts of 0.1 mm, cells of 5 µm), ended as internal errors.
// In millimetres the limit is 14 nm. Everything outside the level-set code stays in metres:
// the functions that make or read a grid convert at the boundary with these helpers.
#pragma once
#include <openvdb/openvdb.h>

namespace latmpm {

constexpr double grid_units_per_metre = 1e3;

// The smallest voxel (m) a level set may have: 0.1 µm, 1e-4 mm, seven times OpenVDB's
// limit of 1.44e-5 mm (a voxel volume of 3e-15 mm³).
constexpr double smallest_voxel_m = 1e-7;

// A uniform scale transform for a voxel of `voxel_m` metres.
inline openvdb::math::Transform::Ptr level_set_transform(double voxel_m) {
  return openvdb::math::Transform::createLinearTransform(voxel_m * grid_units_per_metre);
}

}  // namespace latmpm
