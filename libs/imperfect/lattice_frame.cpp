#include "imperfect/lattice_frame.hpp"

#include <cmath>
#include <cstdlib>

#include "core/errors.hpp"
#include "core/units.hpp"

namespace latmpm {
namespace {

// A length parameter of the source geometry, or NaN when absent.
double length_parameter(const PointSet& points, const std::string& key, const std::string& where) {
  auto it = points.parameters.find(key);
  if (it == points.parameters.end()) return std::nan("");
  return parse_quantity(it->second, dimension::length, where, "/points/parameters/" + key);
}

// Number of cell layers along z from "cells" = "5x5x5" (the last factor) or "layers" = "5".
int layer_count(const PointSet& points, const std::string& where) {
  std::string text;
  std::string key;
  if (auto it = points.parameters.find("layers"); it != points.parameters.end()) {
    key = "layers";
    text = it->second;
  } else if (auto jt = points.parameters.find("cells"); jt != points.parameters.end()) {
    key = "cells";
    text = jt->second;
    if (auto x = text.find_last_of("x×*"); x != std::string::npos) text = text.substr(x + 1);
  } else {
    return 0;
  }
  char* end = nullptr;
  long n = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || n < 1)
    throw InputError(where, "/points/parameters/" + key, "'" + points.parameters.at(key) + "' does not give a number of cell layers");
  return static_cast<int>(n);
}

std::string metres(double v) { return format_millimetres(v, 6); }

}  // namespace

Extent body_extent(const PointSet& points, const std::vector<int>& bodies) {
  std::vector<bool> wanted(points.body_names.size(), false);
  for (int b : bodies) wanted.at(b) = true;
  Extent e;
  for (size_t i = 0; i < points.size(); ++i)
    if (wanted[points.body[i]]) e.add(points.position[i], points.half_size[i]);
  return e;
}

LatticeFrame find_lattice_frame(const PointSet& points, const std::string& where,
                                double layer_height_override) {
  LatticeFrame frame;
  const int lattice = points.body_index("lattice");
  const int bottom = points.body_index("bottom_plate");
  const int top = points.body_index("top_plate");
  std::vector<int> struts;
  if (lattice >= 0) struts.push_back(lattice);

  frame.lattice_zmin = length_parameter(points, "lattice_zmin", where);
  if (std::isnan(frame.lattice_zmin)) {
    if (bottom >= 0) {
      frame.lattice_zmin = body_extent(points, {bottom}).max.z();
      frame.notes.push_back("lattice_zmin not in the file's parameters: using the top of body bottom_plate, " + metres(frame.lattice_zmin));
    } else if (!struts.empty()) {
      frame.lattice_zmin = body_extent(points, struts).min.z();
      frame.notes.push_back("lattice_zmin not in the file's parameters and no bottom_plate: using the bottom of body lattice, " + metres(frame.lattice_zmin));
    } else {
      throw InputError(where, "/points/parameters/lattice_zmin", "absent, and the file has neither a bottom_plate nor a lattice body to find it from");
    }
  }
  frame.lattice_zmax = length_parameter(points, "lattice_zmax", where);
  if (std::isnan(frame.lattice_zmax)) {
    if (top >= 0) {
      frame.lattice_zmax = body_extent(points, {top}).min.z();
      frame.notes.push_back("lattice_zmax not in the file's parameters: using the bottom of body top_plate, " + metres(frame.lattice_zmax));
    } else if (!struts.empty()) {
      frame.lattice_zmax = body_extent(points, struts).max.z();
      frame.notes.push_back("lattice_zmax not in the file's parameters and no top_plate: using the top of body lattice, " + metres(frame.lattice_zmax));
    } else {
      throw InputError(where, "/points/parameters/lattice_zmax", "absent, and the file has neither a top_plate nor a lattice body to find it from");
    }
  }
  if (!(frame.lattice_zmax > frame.lattice_zmin))
    throw InputError(where, "/points/parameters", "the lattice top (" + metres(frame.lattice_zmax) + ") is not above its bottom (" + metres(frame.lattice_zmin) + ")");

  if (layer_height_override > 0) {
    frame.layer_height = layer_height_override;
  } else {
    frame.layer_height = length_parameter(points, "layer_height", where);
    if (std::isnan(frame.layer_height)) {
      frame.layer_height = 0;
      if (int layers = layer_count(points, where); layers > 0) {
        frame.layer_height = (frame.lattice_zmax - frame.lattice_zmin) / layers;
        frame.notes.push_back("layer_height not in the file's parameters: lattice height / " + std::to_string(layers) + " layers = " + metres(frame.layer_height));
      }
    }
  }
  if (frame.layer_height < 0 || frame.layer_height > frame.lattice_zmax - frame.lattice_zmin + 1e-12)
    throw InputError(where, "/points/parameters/layer_height", metres(frame.layer_height) + " does not fit in the lattice height " + metres(frame.lattice_zmax - frame.lattice_zmin));
  return frame;
}

}  // namespace latmpm
