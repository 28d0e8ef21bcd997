// Is the point lattice fine enough for the thinnest strut? Fewer than three points across a
// strut gives a poor bending response; fewer than one can cut a strut apart entirely.
#pragma once
#include <cstddef>
#include <string>

#include "geometry/strut_graph.hpp"

namespace latmpm {

struct StrutResolution {
  bool has_struts = false;
  size_t strut = 0;            // index of the thinnest strut
  double diameter = 0;         // m
  double points_across = 0;    // diameter / (h/ppc)
  double cells_across = 0;     // diameter / h
  enum class Verdict { fine, coarse, too_coarse } verdict = Verdict::fine;  // ≥3, [1,3), <1 points
};

StrutResolution strut_resolution(const StrutGraph& graph, double cell_size, int ppc);

// "thinnest strut 2.4 mm: 7.5 points, 3.75 cells across"
std::string describe(const StrutResolution& r);

}  // namespace latmpm
