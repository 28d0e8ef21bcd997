// Bodies and tagged regions of a point set (docs/formats.md, "Point-set file").
#pragma once
#include <string>
#include <vector>

#include "geometry/strut_graph.hpp"
#include "points/point_set.hpp"

namespace latmpm {

// Bodies of points sampled from a strut graph: a point inside a plate's box belongs to that
// plate (where plate and struts overlap, the plate wins), every other point to the graph's
// strut body. Sets body_names = [strut_body, plate names...] (plates only if they got points).
void assign_strut_graph_bodies(PointSet& points, const StrutGraph& graph);

// Region masks, by lattice layer (z index of the point lattice, Δ = h/ppc):
//   "record"       the lowest layer of the body named "bottom_plate", or of the lowest body
//                  if there is none: the paper's reaction-measuring points (paper A Sec. 5.1);
//   "bottom_layer" the lowest layer of all points;
//   "top_layer"    the highest layer of the topmost body (where the load is applied);
//   one mask per plate body ("bottom_plate", "top_plate"), 1 on that plate's points.
void tag_regions(PointSet& points, const std::vector<std::string>& plate_names);

}  // namespace latmpm
