// The solid of a strut graph (capsule or flat-ended struts and box plates) as an OpenVDB
// narrow-band level set: signed distance in grid units (mm, level_set_units.hpp), negative
// inside. OpenVDB 10 has
// no capsule/tube rasteriser (it arrived in 12.1), so the distances are computed here.
// The union's distance is the minimum over primitives. Every voxel within the band of any
// primitive gets min over all primitives near it (clamped to ±band), so a voxel deep inside
// one strut but in the band of another is never left with the other's positive value; the
// deep interior is then resolved by sign flood fill, so sampling anywhere answers
// inside/outside correctly.
#pragma once
#include <openvdb/openvdb.h>

#include <functional>

#include "geometry/strut_graph.hpp"

namespace latmpm {

// `voxel_size_m`: voxel edge (m), voxel (i, j, k) centred at (i, j, k)·voxel_size.
// `half_width_voxels`: half width of the narrow band in voxels (≥ 1; OpenVDB's usual 3).
// Throws std::invalid_argument for a voxel below smallest_voxel_m or a band under 1 voxel.
openvdb::FloatGrid::Ptr strut_graph_level_set(const StrutGraph& graph, double voxel_size_m,
                                              double half_width_voxels = 3.0);

// The same, calling `progress(fraction_done)` now and then (from the calling thread).
openvdb::FloatGrid::Ptr strut_graph_level_set(const StrutGraph& graph, double voxel_size_m,
                                              double half_width_voxels,
                                              const std::function<void(double)>& progress);

}  // namespace latmpm
