// Structural checks of a strut graph: what the tests assert and the tool's summary reports.
#pragma once
#include <cstddef>
#include <vector>

#include "geometry/strut_graph.hpp"

namespace latmpm {

double strut_length(const StrutGraph& graph, const Strut& strut);

// Pairs of nodes closer than `tolerance` (m): 0 for a well-merged graph.
size_t count_duplicate_nodes(const StrutGraph& graph, double tolerance);
// Struts joining the same two nodes as an earlier strut (either direction).
size_t count_duplicate_struts(const StrutGraph& graph);

// The separate solid pieces formed by the struts and plates: struts sharing a node are
// joined; a strut whose end node lies within its radius (plus `tolerance`) of a plate's box
// is joined to the plate (the capsule reaches it). Nodes without struts are ignored; a plate
// no strut reaches is a piece of its own.
struct Pieces {
  int count = 0;               // connected pieces made of struts and plates
  std::vector<int> of_strut;   // piece of each strut
  std::vector<int> of_plate;   // piece of each plate
  std::vector<int> struts_in;  // number of struts in each piece
};
Pieces connected_pieces(const StrutGraph& graph, double tolerance = 0);

// Number of pieces (connected_pieces(...).count): 1 for a printable specimen.
size_t count_bodies(const StrutGraph& graph, double tolerance);

// Distance from a point to an axis-aligned box (0 inside).
double distance_to_box(const Eigen::Vector3d& x, const Eigen::Vector3d& min, const Eigen::Vector3d& max);

}  // namespace latmpm
