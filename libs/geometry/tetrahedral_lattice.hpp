// The tetrahedral lattice of paper A (Sec. 3, Fig. 1–2) as decided in REFERENCE.md: a
// diamond-like node seen along the diamond [111] axis. Each cell is a tripod — three inclined
// struts of length L at angle φ to the horizontal meeting at a node — plus a vertical strut of
// 2L/3 above the node. Layers are stacked ABC so that every vertical strut ends in a foot of
// the next layer's tripods. Geometry, stacking and footprint rules: docs/geometry.md.
#pragma once
#include "geometry/strut_graph.hpp"

namespace latmpm {

// Which way the tripods point: `abc` has one foot towards −y (feet f_k, see the .cpp), `acb`
// is its mirror image (feet −f_k, one foot towards +y). Both shift each layer by one foot
// vector, so that every vertical strut ends in a foot of the next layer.
enum class Stacking { abc, acb };
// Which 25 (nx·ny) tripod nodes of a layer's triangular lattice are kept: `brick` — the ny
// rows nearest the footprint centre, nx nodes nearest the centre in each (alternate rows
// shifted half a spacing); `rhombic` — the nx × ny parallelogram of lattice vectors whose
// centroid is nearest the centre.
enum class Footprint { brick, rhombic };

struct TetrahedralLattice {
  double strut_length = 0;    // L (m), inclined struts; vertical struts are 2L/3
  double strut_diameter = 0;  // t (m)
  double angle = 0;           // φ (rad) of the inclined struts to the horizontal, in (0, π/2)
  int nodes_per_row = 5, rows = 5, layers = 5;
  Stacking stacking = Stacking::abc;
  Footprint footprint = Footprint::brick;

  double foot_distance() const;  // d = L cos φ: horizontal node–foot distance
  double node_spacing() const;   // a = √3·d: spacing of the tripod nodes in a layer
  double layer_height() const;   // h = L sin φ + 2L/3
};

// The lattice around the footprint centre x = y = 0, bottom feet at z = 0 and the tops of the
// last vertical struts at z = layers·h. No plates. Throws std::invalid_argument for sizes out
// of range (callers validate user input first, see lattice.hpp).
StrutGraph build_tetrahedral_lattice(const TetrahedralLattice& spec);

}  // namespace latmpm
