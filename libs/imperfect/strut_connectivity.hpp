// Is a strut graph one printed body? Struts join at shared nodes; a strut touches a plate
// when its end node lies within its radius of the plate's box (the capsule reaches the
// plate). Used after random strut removal (--missing-struts).
#pragma once
#include <vector>

#include "geometry/strut_graph.hpp"

namespace latmpm {

struct Pieces {
  int count = 0;                // connected pieces made of struts and plates
  std::vector<int> of_strut;    // piece of each strut
  std::vector<int> of_plate;    // piece of each plate
  std::vector<int> struts_in;   // number of struts in each piece
};

Pieces connected_pieces(const StrutGraph& graph);

// Distance from a point to an axis-aligned box (0 inside).
double distance_to_box(const Eigen::Vector3d& x, const Eigen::Vector3d& min, const Eigen::Vector3d& max);

}  // namespace latmpm
