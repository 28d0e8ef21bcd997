#include "geometry/lattice.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

#include "core/errors.hpp"
#include "core/text.hpp"
#include "geometry/parameter_text.hpp"
#include "geometry/plates.hpp"
#include "geometry/unit_cell.hpp"

namespace latmpm {
namespace {

// A lattice built from a spec, before plates: struts from z = 0 up, and the height of one
// cell layer along z (what "shear the top cell layer" needs later).
struct CellLattice {
  StrutGraph graph;
  double layer_height = 0;
};

CellLattice tetrahedral(const LatticeSpec& spec) {
  TetrahedralLattice t;
  t.strut_length = spec.strut_length;
  t.strut_diameter = spec.strut_diameter;
  t.angle = spec.angle;
  t.nodes_per_row = spec.cells[0];
  t.rows = spec.cells[1];
  t.layers = spec.cells[2];
  t.stacking = spec.stacking;
  t.footprint = spec.footprint;
  CellLattice out{build_tetrahedral_lattice(t), t.layer_height()};
  auto& p = out.graph.parameters;
  p["angle"] = quantity_text(spec.angle, "rad");
  p["stacking"] = spec.stacking == Stacking::abc ? "ABC" : "ACB";
  p["footprint"] = spec.footprint == Footprint::brick ? "brick" : "rhombic";
  p["node_spacing"] = quantity_text(t.node_spacing(), "m");
  return out;
}

CellLattice tiled(const UnitCell& cell, const LatticeSpec& spec) {
  CellLattice out{tile_unit_cell(cell, spec.cells[0], spec.cells[1], spec.cells[2],
                                 spec.strut_diameter / 2),
                  cell.lattice_vectors(2, 2)};
  out.graph.parameters["cell_size"] = quantity_text(cell.lattice_vectors(0, 0), "m");
  return out;
}

struct CellType {
  const char* name;
  bool uses_angle;
  std::function<CellLattice(const LatticeSpec&)> build;
};

// The cell catalogue: one line per cell type.
const std::vector<CellType>& cell_types() {
  static const std::vector<CellType> types = {
      {"tetrahedral", true, tetrahedral},
      {"bcc", false, [](const LatticeSpec& s) { return tiled(bcc_cell(s.strut_length), s); }},
      {"octet", false, [](const LatticeSpec& s) { return tiled(octet_cell(s.strut_length), s); }},
  };
  return types;
}

const CellType* find_cell(const std::string& name) {
  for (const auto& c : cell_types())
    if (name == c.name) return &c;
  return nullptr;
}

}  // namespace

std::vector<std::string> cell_names() {
  std::vector<std::string> names;
  for (const auto& c : cell_types()) names.push_back(c.name);
  return names;
}

bool cell_uses_angle(const std::string& cell) {
  const CellType* c = find_cell(cell);
  return c && c->uses_angle;
}

std::vector<std::string> preset_names() {
  return {"T1P20", "T1P30", "T1P40", "T2P20", "T2P30", "T2P40"};
}

LatticeSpec preset_lattice(const std::string& preset) {
  // Paper A Sec. 3: TXPY, X = 1 → t = 1.6 mm, X = 2 → t = 2.4 mm; Y = φ in degrees.
  const bool known = preset.size() == 5 && preset[0] == 'T' && (preset[1] == '1' || preset[1] == '2') &&
                     preset[2] == 'P' && (preset.substr(3) == "20" || preset.substr(3) == "30" ||
                                          preset.substr(3) == "40");
  if (!known)
    throw InputError("--preset", "", "unknown preset '" + preset + "' (known: " + joined(preset_names()) + ")");
  LatticeSpec spec;
  spec.cell = "tetrahedral";
  spec.name = preset;
  spec.strut_length = 8e-3;
  spec.strut_diameter = preset[1] == '1' ? 1.6e-3 : 2.4e-3;
  spec.angle = std::stoi(preset.substr(3)) * M_PI / 180.0;
  spec.cells = {5, 5, 5};
  spec.plate_thickness = 3e-3;
  return spec;
}

std::array<int, 3> parse_cell_counts(const std::string& text) {
  std::array<int, 3> counts{};
  char x1 = 0, x2 = 0;
  int consumed = 0;
  const int fields = std::sscanf(text.c_str(), "%d%c%d%c%d%n", &counts[0], &x1, &counts[1], &x2,
                                 &counts[2], &consumed);
  if (fields != 5 || (x1 != 'x' && x1 != 'X') || (x2 != 'x' && x2 != 'X') ||
      size_t(consumed) != text.size())
    throw InputError("--cells", "", "'" + text + "' is not of the form NXxNYxNZ (e.g. 5x5x5)");
  for (int c : counts)
    if (c < 1) throw InputError("--cells", "", "every cell count must be at least 1, got '" + text + "'");
  return counts;
}

Stacking parse_stacking(const std::string& text) {
  if (text == "ABC" || text == "abc") return Stacking::abc;
  if (text == "ACB" || text == "acb") return Stacking::acb;
  throw InputError("--stacking", "", "unknown stacking '" + text + "' (known: ABC, ACB)");
}

Footprint parse_footprint(const std::string& text) {
  if (text == "brick") return Footprint::brick;
  if (text == "rhombic") return Footprint::rhombic;
  throw InputError("--footprint", "", "unknown footprint '" + text + "' (known: brick, rhombic)");
}

void validate(const LatticeSpec& spec) {
  const CellType* cell = find_cell(spec.cell);
  if (!cell)
    throw InputError("--cell", "", "unknown cell type '" + spec.cell + "' (known: " + joined(cell_names()) + ")");
  auto positive = [](double v, const char* option, const char* what) {
    if (!(v > 0) || !std::isfinite(v)) throw InputError(option, "", std::string(what) + " must be positive");
  };
  positive(spec.strut_length, "--strut-length", "the strut length");
  positive(spec.strut_diameter, "--strut-diameter", "the strut diameter");
  for (int axis = 0; axis < 3; ++axis)
    if (spec.cells[axis] < 1) throw InputError("--cells", "", "every cell count must be at least 1");
  if (spec.cells[0] * double(spec.cells[1]) * spec.cells[2] > 1e6)
    throw InputError("--cells", "", "more than a million cells");
  if (cell->uses_angle) {
    if (!(spec.angle > 0 && spec.angle < M_PI / 2))
      throw InputError("--angle", "", "must lie strictly between 0deg and 90deg");
  } else if (spec.angle != 0) {
    throw InputError("--angle", "", "applies only to the tetrahedral cell, not '" + spec.cell + "'");
  }
  if (spec.plate_thickness < 0 || !std::isfinite(spec.plate_thickness))
    throw InputError("--plates", "", "the plate thickness must be positive");
  if (spec.plate_margin < 0 || !std::isfinite(spec.plate_margin))
    throw InputError("--plate-margin", "", "must not be negative");
  if (spec.strut_diameter >= spec.strut_length)
    throw InputError("--strut-diameter", "", "must be smaller than the strut length");
  if (spec.plate_thickness > 0 && spec.plate_thickness < spec.strut_diameter / 2)
    throw InputError("--plates", "", "must be at least the strut radius (" + quantity_text(spec.strut_diameter / 2, "m") +
                                         "), or the round strut ends poke through the plates");
}

StrutGraph build_lattice(const LatticeSpec& spec) {
  validate(spec);
  CellLattice lattice = find_cell(spec.cell)->build(spec);
  StrutGraph& g = lattice.graph;
  g.name = spec.name.empty() ? spec.cell : spec.name;
  g.strut_body = "lattice";
  centre_footprint(g);
  if (spec.plate_thickness > 0) {
    add_plates(g, spec.plate_thickness, spec.plate_margin);
  } else {  // the solid, round ends included, starts at z = 0
    const double lowest = solid_bounds(g).min().z();
    for (auto& n : g.nodes) n.z() -= lowest;
  }
  double zmin = INFINITY, zmax = -INFINITY;
  for (const auto& n : g.nodes) zmin = std::min(zmin, n.z()), zmax = std::max(zmax, n.z());
  auto& p = g.parameters;
  p["cell"] = spec.cell;
  p["strut_length"] = quantity_text(spec.strut_length, "m");
  p["strut_diameter"] = quantity_text(spec.strut_diameter, "m");
  p["cells"] = std::to_string(spec.cells[0]) + "x" + std::to_string(spec.cells[1]) + "x" +
               std::to_string(spec.cells[2]);
  p["layer_height"] = quantity_text(lattice.layer_height, "m");
  p["lattice_zmin"] = quantity_text(zmin, "m");  // strut-node range: plates meet the lattice here
  p["lattice_zmax"] = quantity_text(zmax, "m");
  // The struts' x–y bounding box, radius included: the area an effective modulus
  // E* = k H / A refers to (docs/post.md), and the footprint of the relative density.
  const Eigen::AlignedBox3d footprint = solid_bounds(g, true);
  p["footprint_area"] = quantity_text(footprint.sizes().x() * footprint.sizes().y(), "m^2");
  p["plate_thickness"] = quantity_text(spec.plate_thickness, "m");
  if (spec.plate_thickness > 0) p["plate_margin"] = quantity_text(spec.plate_margin, "m");
  return lattice.graph;
}

}  // namespace latmpm
