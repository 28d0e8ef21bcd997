// Solid plates under and over a lattice, as printed with the paper's specimens (paper A
// Sec. 3: 3 mm plates of the same resin). Strut ends on the lattice's lowest and highest
// nodes touch the plate surfaces, so round ends reach half a sphere into the plates and
// the struts and plates form one body.
#pragma once
#include <Eigen/Geometry>

#include "geometry/strut_graph.hpp"

namespace latmpm {

// Bounding box of the struts (radius included; capsules or flat cylinders as the graph's
// ends say) and, unless `struts_only`, of the plates.
Eigen::AlignedBox3d solid_bounds(const StrutGraph& graph, bool struts_only = false);

// Shifts the graph so that its strut solid's bounding box is centred on x = y = 0.
void centre_footprint(StrutGraph& graph);

// Shifts the graph up by `thickness` and adds "bottom_plate" (z from 0 to thickness) and
// "top_plate" (thickness above the highest node), spanning the struts' bounding box in x and
// y plus `margin` on each side. The lattice's own z range is taken from its nodes.
void add_plates(StrutGraph& graph, double thickness, double margin);

}  // namespace latmpm
