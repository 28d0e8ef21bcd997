// A whole lattice specimen from a few numbers: the cell type tiled nx × ny × nz times, its
// footprint centred on x = y = 0, optional top and bottom plates, and the parameters later
// tools read (layer_height, lattice_zmin...). The paper's six specimens are presets.
// Errors in a spec throw InputError naming the latmpm-lattice option (--strut-length ...).
#pragma once
#include <array>
#include <string>
#include <vector>

#include "geometry/strut_graph.hpp"
#include "geometry/tetrahedral_lattice.hpp"

namespace latmpm {

struct LatticeSpec {
  std::string cell = "tetrahedral";  // one of cell_names()
  std::string name;                  // e.g. "T2P30"; empty: the cell name
  double strut_length = 0;           // m (tetrahedral: the inclined struts, L)
  double strut_diameter = 0;         // m
  double angle = 0;                  // rad; tetrahedral only (0 = not given)
  std::array<int, 3> cells{5, 5, 5};  // tetrahedral: nodes per row, rows, layers
  Stacking stacking = Stacking::abc;       // tetrahedral only
  Footprint footprint = Footprint::brick;  // tetrahedral only
  double plate_thickness = 0;  // m; 0: no plates; else at least the strut radius
  double plate_margin = 0;     // m the plates overhang the lattice on every side
};

// Paper A's specimens T1P20 ... T2P40 (Sec. 3): L = 8 mm, t = 1.6 mm (T1) or 2.4 mm (T2),
// φ = 20°, 30° or 40°, 5 × 5 × 5 cells, 3 mm plates. Unknown name: InputError("--preset").
LatticeSpec preset_lattice(const std::string& preset);
std::vector<std::string> preset_names();

// Cell types: "tetrahedral", "bcc", "octet". Adding one: a UnitCell function (unit_cell.hpp)
// and one line in the table in lattice.cpp.
std::vector<std::string> cell_names();
bool cell_uses_angle(const std::string& cell);

// Option values in words; errors name the option (--cells, --stacking, --footprint).
std::array<int, 3> parse_cell_counts(const std::string& text);  // "5x5x5"
Stacking parse_stacking(const std::string& text);               // "ABC", "ACB"
Footprint parse_footprint(const std::string& text);             // "brick", "rhombic"

// Throws InputError naming the option for anything out of range.
void validate(const LatticeSpec& spec);
// The specimen: lattice between z = plate_thickness and plate_thickness + H, plates below and
// above covering the lattice's footprint (struts included) plus plate_margin. Without plates
// the solid (round ends included) starts at z = 0.
StrutGraph build_lattice(const LatticeSpec& spec);

}  // namespace latmpm
