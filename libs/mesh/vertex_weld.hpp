// Welding near-coincident vertices, as admesh --nearby does. CAD exports write the corner
// shared by several facets with slightly different coordinates (rounding noise such as
// ±3e-16 where the value is 0), so read_stl's exact merge leaves the facets unconnected and
// a good solid looks open. Vertices closer than a tolerance relative to the part's size are
// merged before the closed-solid checks.
#pragma once
#include <cstddef>
#include <string>

#include "mesh/triangle_mesh.hpp"

namespace latmpm {

struct WeldReport {
  double tolerance = 0;      // m, the distance below which vertices were merged
  size_t vertices_welded = 0;  // vertices merged into another
  double largest_gap = 0;    // m, the farthest a welded vertex was from its representative
};

// Default tolerance: this fraction of the bounding-box diagonal. Single precision resolves
// about 6e-8 of a coordinate's magnitude, so 1e-6 of the part is a few float steps: noise, not
// a feature.
constexpr double default_weld_fraction = 1e-6;

// Merges every vertex within `relative_tolerance` × (bounding-box diagonal) of another
// (transitively: clusters merge into their lowest-indexed vertex), renumbers the triangles
// and drops unused vertices. Triangles that collapse keep their repeated vertex (check_mesh
// counts them as degenerate; repair removes them).
WeldReport weld_nearby_vertices(TriangleMesh& mesh, double relative_tolerance = default_weld_fraction);

// "welded 12 vertices closer than 1e-05 mm (largest gap 3e-13 mm)" or "".
std::string describe(const WeldReport& report);

}  // namespace latmpm
