#include <cmath>

#include "core/errors.hpp"
#include "core/hdf5_file.hpp"
#include "geometry/strut_graph.hpp"

namespace latmpm {

bool holds_strut_graph(const Hdf5File& file) {
  return file.exists("/geometry") && file.has_attribute("/geometry", "kind") &&
         file.string_attribute("/geometry", "kind") == "strut_graph";
}

void write_strut_graph(Hdf5File& file, const StrutGraph& g) {
  std::vector<double> nodes;
  nodes.reserve(3 * g.nodes.size());
  for (const auto& n : g.nodes) nodes.insert(nodes.end(), {n.x(), n.y(), n.z()});
  std::vector<int32_t> ends;
  std::vector<double> radius;
  for (const auto& s : g.struts) {
    ends.insert(ends.end(), {s.a, s.b});
    radius.push_back(s.radius);
  }
  std::vector<std::string> plate_names;
  std::vector<double> boxes;
  for (const auto& p : g.plates) {
    plate_names.push_back(p.name);
    boxes.insert(boxes.end(), {p.min.x(), p.min.y(), p.min.z(), p.max.x(), p.max.y(), p.max.z()});
  }
  std::vector<std::string> keys, values;
  for (const auto& [k, v] : g.parameters) {
    keys.push_back(k);
    values.push_back(v);
  }
  file.create_group("/geometry");
  file.set_attribute("/geometry", "kind", "strut_graph");
  file.set_attribute("/geometry", "name", g.name);
  file.set_attribute("/geometry", "strut_body", g.strut_body);
  file.set_attribute("/geometry", "length_unit", "m");
  file.set_attribute("/geometry", "strut_ends", g.strut_ends == StrutEnds::flat ? "flat" : "round");
  file.write("/geometry/nodes", nodes, {g.nodes.size(), 3});
  file.write("/geometry/struts", ends, {g.struts.size(), 2});
  file.write("/geometry/strut_radius", radius, {g.struts.size()});
  file.write_strings("/geometry/plates/names", plate_names);
  file.write("/geometry/plates/boxes", boxes, {g.plates.size(), 6});
  file.write_strings("/geometry/parameters/keys", keys);
  file.write_strings("/geometry/parameters/values", values);
}

StrutGraph read_strut_graph(const Hdf5File& file) {
  auto fail = [&](const std::string& field, const std::string& problem) {
    throw InputError(file.path(), field, problem);
  };
  if (!holds_strut_graph(file)) fail("/geometry", "not a latmpm strut-graph file");
  StrutGraph g;
  g.name = file.string_attribute("/geometry", "name");
  g.strut_body = file.string_attribute("/geometry", "strut_body");
  if (file.has_attribute("/geometry", "strut_ends")) {  // optional: older files are all round
    std::string ends = file.string_attribute("/geometry", "strut_ends");
    if (ends == "flat")
      g.strut_ends = StrutEnds::flat;
    else if (ends != "round")
      fail("/geometry@strut_ends", "'" + ends + "' is neither 'round' nor 'flat'");
  }
  std::vector<size_t> dims;
  auto nodes = file.read_doubles("/geometry/nodes", &dims);
  if (dims.size() != 2 || dims[1] != 3) fail("/geometry/nodes", "expected an N×3 array");
  for (size_t i = 0; i < dims[0]; ++i) {
    Eigen::Vector3d p(nodes[3 * i], nodes[3 * i + 1], nodes[3 * i + 2]);
    if (!p.allFinite()) fail("/geometry/nodes", "node " + std::to_string(i) + " is not finite");
    g.nodes.push_back(p);
  }
  auto ends = file.read_int32("/geometry/struts", &dims);
  if (dims.size() != 2 || dims[1] != 2) fail("/geometry/struts", "expected an M×2 array");
  auto radius = file.read_doubles("/geometry/strut_radius");
  if (radius.size() != dims[0]) fail("/geometry/strut_radius", "length differs from /geometry/struts");
  for (size_t i = 0; i < dims[0]; ++i) {
    Strut s{ends[2 * i], ends[2 * i + 1], radius[i]};
    if (s.a < 0 || s.b < 0 || size_t(s.a) >= g.nodes.size() || size_t(s.b) >= g.nodes.size())
      fail("/geometry/struts", "strut " + std::to_string(i) + " names a node that does not exist");
    if (!(s.radius > 0) || !std::isfinite(s.radius))
      fail("/geometry/strut_radius", "strut " + std::to_string(i) + " has a radius that is not positive");
    g.struts.push_back(s);
  }
  auto names = file.read_strings("/geometry/plates/names");
  auto boxes = file.read_doubles("/geometry/plates/boxes", &dims);
  if (boxes.size() != 6 * names.size()) fail("/geometry/plates/boxes", "expected one 6-vector per plate name");
  for (size_t i = 0; i < names.size(); ++i) {
    Plate p{names[i], {boxes[6 * i], boxes[6 * i + 1], boxes[6 * i + 2]},
            {boxes[6 * i + 3], boxes[6 * i + 4], boxes[6 * i + 5]}};
    if (!((p.max - p.min).array() > 0).all())
      fail("/geometry/plates/boxes", "plate '" + p.name + "' has no volume (max <= min)");
    g.plates.push_back(p);
  }
  auto keys = file.read_strings("/geometry/parameters/keys");
  auto values = file.read_strings("/geometry/parameters/values");
  if (keys.size() != values.size()) fail("/geometry/parameters", "keys and values differ in length");
  for (size_t i = 0; i < keys.size(); ++i) g.parameters[keys[i]] = values[i];
  return g;
}

}  // namespace latmpm
