// A column of points between two plates, small enough for a tool run of a second: the test
// scene of tests/solve. Points follow the grid alignment rule of points/point_set.hpp.
#pragma once
#include <string>

#include "points/point_set.hpp"

namespace latmpm::test {

struct TinyColumn {
  double cell = 1e-3;   // m
  int ppc = 2;
  int width_cells = 2;  // square cross-section, cells per side
  int height_cells = 8;
  int plate_cells = 1;  // plate thickness in cells
};

// Column (body "column") from z = plate to z = plate + height; plates "bottom_plate" and
// "top_plate" of the same footprint below and above. The column's bottom layer of points carries the
// "record" tag.
PointSet tiny_column(const TinyColumn& spec);
void write_points(const PointSet& points, const std::string& path);

}  // namespace latmpm::test
