// A lattice cell type as data: its struts in local coordinates plus the three lattice vectors
// that tile it. A new periodic cell is one small function returning a UnitCell (see
// bcc_cell.cpp, octet_cell.cpp); tile_unit_cell() does the rest. Struts on a cell's faces
// may be listed by every cell that owns the face: tiling merges the copies.
#pragma once
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "geometry/strut_graph.hpp"

namespace latmpm {

struct UnitCell {
  std::string name;                 // "bcc", "octet"
  Eigen::Matrix3d lattice_vectors;  // columns a1, a2, a3 (m); a3 is the stacking (z) direction
  std::vector<std::array<Eigen::Vector3d, 2>> struts;  // end points in cell coordinates (m)
};

// nx × ny × nz copies of `cell`, copy (i, j, k) shifted by i·a1 + j·a2 + k·a3, with coincident
// nodes merged and duplicate struts removed. All struts get `strut_radius` (m).
StrutGraph tile_unit_cell(const UnitCell& cell, int nx, int ny, int nz, double strut_radius);

// The periodic cells shipped with latmpm, sized by their strut length (m).
// Body-centred cubic: the 8 half-diagonals of a cube of edge 2L/√3.
UnitCell bcc_cell(double strut_length);
// Octet truss: the 12 nearest-neighbour bonds of face-centred cubic, cube edge √2·L.
UnitCell octet_cell(double strut_length);

}  // namespace latmpm
