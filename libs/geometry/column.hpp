// The buckling column of paper A Sec. 4: a solid cylinder of diameter t and length L along z.
// Decision (docs/geometry.md): one strut with flat ends (StrutGraph::strut_ends = flat), so
// the solid is exactly L long, not L + t as a capsule would be. Optional end plates of
// the column's own footprint (a square of side t, plus a margin) sit against its ends.
#pragma once
#include "geometry/strut_graph.hpp"

namespace latmpm {

struct ColumnSpec {
  double diameter = 0;             // m
  double length = 0;               // m
  double end_plate_thickness = 0;  // m; 0: no end plates
  double plate_margin = 0;         // m the end plates overhang the column on each side
};

// Throws InputError naming the latmpm-lattice option for anything out of range.
void validate(const ColumnSpec& spec);
// Column axis x = y = 0, from z = end_plate_thickness to end_plate_thickness + length;
// body "column", plates "bottom_plate", "top_plate".
StrutGraph build_column(const ColumnSpec& spec);

}  // namespace latmpm
