#include "post/specimen.hpp"

#include <cmath>
#include <toml++/toml.h>

#include "core/errors.hpp"
#include "core/hdf5_file.hpp"
#include "core/units.hpp"
#include "points/point_set.hpp"

namespace latmpm::post {

namespace {

// A dimensional scene value ("10MPa"), or NaN with a note when absent or malformed.
double scene_quantity(const toml::node* node, const Dimension& dimension, const std::string& key,
                      SpecimenFacts& facts) {
  if (!node || !node->is_string()) {
    facts.notes.push_back("scene.toml: " + key + " not found");
    return SpecimenFacts::unknown;
  }
  try {
    return parse_quantity(**node->as_string(), dimension, "scene.toml", key);
  } catch (const InputError& e) {
    facts.notes.push_back(e.what());
    return SpecimenFacts::unknown;
  }
}

double quantity_parameter(const PointSet& points, const std::string& key, const Dimension& dimension,
                          const std::string& file) {
  auto it = points.parameters.find(key);
  if (it == points.parameters.end()) return SpecimenFacts::unknown;
  return parse_quantity(it->second, dimension, file, "/points/parameters/" + key);
}

double length_parameter(const PointSet& points, const std::string& key, const std::string& file) {
  return quantity_parameter(points, key, dimension::length, file);
}

}  // namespace

SpecimenFacts read_specimen_facts(const std::string& scene_path) {
  SpecimenFacts facts;
  toml::table doc;
  try {
    doc = toml::parse_file(scene_path);
  } catch (const toml::parse_error& e) {
    throw InputError(scene_path, "line " + std::to_string(e.source().begin.line),
                     std::string(e.description()));
  }

  if (auto scaling = doc["time"]["mass_scaling"].value<double>()) facts.mass_scaling = *scaling;

  // Deformable bodies and their material.
  if (const toml::table* bodies = doc["bodies"].as_table()) {
    for (const auto& [name, node] : *bodies) {
      const toml::table* body = node.as_table();
      if (!body || (*body)["role"].value_or(std::string()) != "deformable") continue;
      facts.deformable_bodies.emplace_back(name.str());
      if (facts.deformable_bodies.size() > 1) continue;
      const std::string key = "bodies." + std::string(name.str()) + ".material";
      facts.youngs_modulus = scene_quantity((*body)["material"]["E"].node(), dimension::pressure, key + ".E", facts);
      facts.density = scene_quantity((*body)["material"]["density"].node(), dimension::density, key + ".density", facts);
    }
  }
  if (facts.deformable_bodies.empty()) facts.notes.push_back("scene.toml: no deformable body");
  if (facts.deformable_bodies.size() > 1)
    facts.notes.push_back("scene.toml: several deformable bodies; E and density are those of '" +
                          facts.deformable_bodies.front() + "', the mass uses each body's density");

  // Point files: volumes of the deformable bodies and the geometry parameters.
  double mass = 0;
  bool mass_known = !facts.deformable_bodies.empty();
  if (const toml::array* files = doc["points"].as_array()) {
    for (const auto& entry : *files) {
      const std::string file = entry.as_table() ? (*entry.as_table())["file"].value_or(std::string()) : "";
      if (file.empty()) continue;
      facts.point_files.push_back(file);
      try {
        Hdf5File h5(file, Hdf5File::Mode::read);
        const PointSet points = read_point_set(h5);
        for (const std::string& body : facts.deformable_bodies) {
          const int b = points.body_index(body);
          if (b < 0) continue;
          double density = facts.density;
          if (body != facts.deformable_bodies.front())
            density = scene_quantity(doc["bodies"][body]["material"]["density"].node(), dimension::density,
                                     "bodies." + body + ".material.density", facts);
          for (size_t i = 0; i < points.size(); ++i)
            if (points.body[i] == b) mass += points.volume[i] * density;
        }
        if (facts.cell.empty() && points.parameters.count("cell")) facts.cell = points.parameters.at("cell");
        if (std::isnan(facts.strut_diameter)) facts.strut_diameter = length_parameter(points, "strut_diameter", file);
        if (std::isnan(facts.strut_length)) facts.strut_length = length_parameter(points, "strut_length", file);
        if (std::isnan(facts.gauge_length))
          facts.gauge_length = length_parameter(points, "lattice_zmax", file) - length_parameter(points, "lattice_zmin", file);
        if (std::isnan(facts.footprint_area))
          facts.footprint_area = quantity_parameter(points, "footprint_area", dimension::area, file);
      } catch (const InputError& e) {
        facts.notes.push_back(std::string("point file unreadable (") + e.what() + "): no mass or geometry from it");
        mass_known = false;
      }
    }
  }
  if (facts.point_files.empty()) {
    facts.notes.push_back("scene.toml: no [[points]] file named");
    mass_known = false;
  }
  if (mass_known && std::isfinite(mass) && mass > 0) facts.mass = mass;
  if (std::isnan(facts.gauge_length))
    facts.notes.push_back("no lattice_zmin/lattice_zmax in the point files' parameters: no strains");
  return facts;
}

}  // namespace latmpm::post
