// Will the voxelizer's work fit? Before anything is allocated, the solid's volume and surface
// area give the number of material points (volume / Δ³) and of level-set voxels (area / v²
// times the band's width), hence the memory; and its bounds in voxels must fit OpenVDB's
// integer coordinates. A part given in the wrong unit (metres read as millimetres, or the
// reverse) shows up here: it is refused with its extent and the unit that would make sense,
// instead of ending as "zero volume" or in std::bad_alloc.
#pragma once
#include <Eigen/Geometry>
#include <string>

#include "geometry/strut_graph.hpp"
#include "mesh/triangle_mesh.hpp"
#include "voxelize/voxelize.hpp"

namespace latmpm {

struct ResourceEstimate {
  Eigen::AlignedBox3d bounds;  // m, of the solid
  double volume = 0, area = 0;  // m³, m²
  double points = 0;            // material points expected, volume / Δ³
  double band_voxels = 0;       // level-set voxels, area / v² × band width (both sides)
  double bytes = 0;             // peak memory estimate of the two
  double largest_index = 0;     // largest |coordinate| / voxel over the bounds
};

// The mesh must be closed (its volume is taken by the divergence theorem); lengths in metres.
ResourceEstimate estimate_resources(const TriangleMesh& mesh, const VoxelizeOptions& options);
// Struts as capsules and plates as boxes, overlaps counted twice (an upper estimate).
ResourceEstimate estimate_resources(const StrutGraph& graph, const VoxelizeOptions& options);

// Throws InputError(where, field, ...) when the solid is too far out or too large for the
// voxel size (more than `max_index_extent` voxels from the origin), needs more than
// `max_bytes` of memory, or would get no point at all (smaller than a point spacing).
// `unit_hint` is appended to the message (see unit_hint()).
void check_resources(const ResourceEstimate& estimate, const VoxelizeOptions& options, double max_bytes,
                     const std::string& where, const std::string& unit_hint = "");

// Voxels from the origin a level set can index: the strut rasteriser packs leaf coordinates
// in 21 bits (±2^20 leaves of 8 voxels), OpenVDB's Coord is int32.
constexpr double max_index_extent = 8.0e6;

// The machine's physical memory (bytes): the default of --max-memory.
double physical_memory_bytes();

// "16GB", "512MB", "2GiB", "1.5TB" → bytes. Throws InputError(where, "", ...).
double parse_bytes(const std::string& text, const std::string& where);

// "x [0, 0.02] y [...] z [...] mm (0.02 x 0.02 x 0.01 mm)"
std::string describe_extent(const Eigen::AlignedBox3d& bounds);

// When a part of this extent (metres, read with `metres_per_unit`) is implausible for a
// printed specimen — smaller than a point spacing or larger than 2 m — and another common
// length unit makes it 1 mm to 2 m across: "did you mean --units m?". Else "".
std::string unit_hint(const Eigen::AlignedBox3d& bounds, double metres_per_unit, double spacing);

}  // namespace latmpm
