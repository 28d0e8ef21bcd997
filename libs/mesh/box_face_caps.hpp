// Closing the openings of a part clipped at its bounding box (a lattice cut out of a larger
// one, a strut sliced at the build plate): a border loop that lies in a face plane of the
// bounding box is closed by the planar region it bounds on that face — a constrained
// Delaunay triangulation of all the loops on the face, inside where the loops nest an odd
// number of times, so a ring (a tube's end) gets a ring and not two overlapping discs.
// A general hole filler would bulge the cap inward or fill a ring's hole (−2.1 % volume on a
// clipped lattice). Internal to the mesh library (CGAL types).
#pragma once
#include <cstddef>

#include "mesh/cgal_surface.hpp"

namespace latmpm {

struct CapReport {
  size_t loops_capped = 0, faces_added = 0;
  double area = 0;  // m², of the caps
};

// Caps every border loop of `surface` lying (within `tolerance`, m) in a face plane of the
// bounding box of its vertices. Loops it cannot cap (crossing loops on a face) stay open.
CapReport cap_box_face_openings(cgal::Surface& surface, double tolerance);

}  // namespace latmpm
