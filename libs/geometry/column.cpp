#include "geometry/column.hpp"

#include <cmath>

#include "core/errors.hpp"
#include "geometry/parameter_text.hpp"

namespace latmpm {

void validate(const ColumnSpec& spec) {
  if (!(spec.diameter > 0) || !std::isfinite(spec.diameter))
    throw InputError("--diameter", "", "the column diameter must be positive");
  if (!(spec.length > 0) || !std::isfinite(spec.length))
    throw InputError("--length", "", "the column length must be positive");
  if (spec.end_plate_thickness < 0 || !std::isfinite(spec.end_plate_thickness))
    throw InputError("--end-plates", "", "the end-plate thickness must be positive");
  if (spec.plate_margin < 0 || !std::isfinite(spec.plate_margin))
    throw InputError("--plate-margin", "", "must not be negative");
}

StrutGraph build_column(const ColumnSpec& spec) {
  validate(spec);
  const double t = spec.end_plate_thickness, r = spec.diameter / 2;
  StrutGraph g;
  g.name = "column";
  g.strut_body = "column";
  g.strut_ends = StrutEnds::flat;
  g.nodes = {{0, 0, t}, {0, 0, t + spec.length}};
  g.struts = {{0, 1, r}};
  if (t > 0) {
    const double half = r + spec.plate_margin;
    g.plates.push_back({"bottom_plate", {-half, -half, 0}, {half, half, t}});
    g.plates.push_back({"top_plate", {-half, -half, t + spec.length}, {half, half, 2 * t + spec.length}});
  }
  auto& p = g.parameters;
  p["cell"] = "column";
  p["diameter"] = quantity_text(spec.diameter, "m");
  p["length"] = quantity_text(spec.length, "m");
  p["strut_diameter"] = quantity_text(spec.diameter, "m");
  p["strut_length"] = quantity_text(spec.length, "m");
  p["strut_ends"] = "flat";
  p["lattice_zmin"] = quantity_text(t, "m");
  p["lattice_zmax"] = quantity_text(t + spec.length, "m");
  p["plate_thickness"] = quantity_text(t, "m");
  return g;
}

}  // namespace latmpm
