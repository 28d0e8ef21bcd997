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

// Number of separate solid bodies formed by the struts and plates: struts sharing a node are
// joined; a strut whose end node lies within its radius (plus `tolerance`) of a plate is
// joined to the plate. Nodes without struts are ignored. 1 for a printable specimen.
size_t count_bodies(const StrutGraph& graph, double tolerance);

}  // namespace latmpm
