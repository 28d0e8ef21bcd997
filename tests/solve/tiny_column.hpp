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

// The scene of the tiny column (points file "column.h5" beside it): the top plate driven
// down at 100 mm/s by 0.2 mm, uGIMP on a 1 mm grid; a few hundred steps.
inline const std::string tiny_column_scene = R"([run]
end = { plate_displacement = "0.2mm" }
[grid]
cell = "1mm"
shape = "ugimp"
[time]
cfl = 0.3
mass_scaling = 6
[[points]]
file = "column.h5"
[bodies.column]
role = "deformable"
material = { E = "10MPa", nu = 0.4, density = "1050kg/m^3" }
[bodies.bottom_plate]
role = "fixed"
[bodies.top_plate]
role = "driven"
velocity = ["0mm/s", "0mm/s", "-100mm/s"]
[output]
series_every = 25
snapshot_every = 100
)";
void write_points(const PointSet& points, const std::string& path);

}  // namespace latmpm::test
