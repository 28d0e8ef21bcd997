// Repairs what CGAL can repair in a triangle soup so that it becomes a closed solid:
// merge duplicate points, drop degenerate and duplicate faces, stitch coincident borders,
// close openings on the bounding box's faces with planar caps (a part clipped at its box,
// box_face_caps.hpp), fill small holes, orient the faces consistently and outward. Says what
// it did, and how much of the surface it had to invent (`filled_area`): a mesh that needed
// much is not a solid that lost a few faces but an open sheet or a triangle soup.
// Anything it cannot fix (large holes, non-manifold fans) is left for check_mesh to report:
// the voxelizer refuses a mesh that is still not closed.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "mesh/triangle_mesh.hpp"

namespace latmpm {

struct RepairOptions {
  // Holes whose border has at most this many edges are triangulated (CGAL triangulate_hole);
  // bigger openings are probably intended or a sign of a broken export, so are left open.
  size_t max_hole_edges = 1000;
};

struct RepairReport {
  size_t degenerate_faces_removed = 0;
  size_t duplicate_faces_removed = 0;   // also counts faces dropped by CGAL's soup repair
  size_t points_merged = 0;
  size_t vertices_split = 0;            // non-manifold vertices duplicated to orient the soup
  size_t edges_stitched = 0;            // pairs of coincident border halfedges joined
  size_t loops_capped = 0, cap_faces_added = 0;  // openings closed on the box's faces
  size_t holes_filled = 0, hole_faces_added = 0;
  size_t holes_left = 0;                // too large to fill
  size_t components_reversed = 0;       // connected components flipped to face outward
  double cap_area = 0, filled_area = 0;  // m², added by box-face caps and by hole filling
  double surface_area = 0;              // m², of the repaired mesh
  // One line per action taken, for the tool's summary ("filled 1 hole with 1 triangle").
  std::vector<std::string> actions;
};

RepairReport repair_mesh(TriangleMesh& mesh, const RepairOptions& options = {});

// Largest share of the repaired surface that hole filling (not box-face caps) may have
// added for the result to count as a solid: a few missing faces, not half a sheet.
constexpr double max_filled_area_fraction = 0.05;

}  // namespace latmpm
