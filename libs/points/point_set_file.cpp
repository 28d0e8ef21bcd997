#include "core/errors.hpp"
#include "core/hdf5_file.hpp"
#include "points/point_set.hpp"

namespace latmpm {
namespace {

std::vector<double> flatten(const std::vector<Eigen::Vector3d>& v) {
  std::vector<double> out;
  out.reserve(3 * v.size());
  for (const auto& p : v) out.insert(out.end(), {p.x(), p.y(), p.z()});
  return out;
}

std::vector<Eigen::Vector3d> unflatten(const Hdf5File& file, const std::string& dataset) {
  std::vector<size_t> dims;
  auto flat = file.read_doubles(dataset, &dims);
  if (dims.size() != 2 || dims[1] != 3) throw InputError(file.path(), dataset, "expected an N×3 array");
  std::vector<Eigen::Vector3d> out(dims[0]);
  for (size_t i = 0; i < dims[0]; ++i) out[i] = {flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]};
  return out;
}

}  // namespace

bool holds_point_set(const Hdf5File& file) {
  return file.exists("/points") && file.has_attribute("/points", "kind") &&
         file.string_attribute("/points", "kind") == "point_set";
}

void write_point_set(Hdf5File& file, const PointSet& p) {
  const size_t n = p.size();
  file.create_group("/points");
  file.set_attribute("/points", "kind", "point_set");
  file.set_attribute("/points", "cell_size", p.cell_size);
  file.set_attribute("/points", "ppc", int64_t{p.ppc});
  file.set_attribute("/points", "length_unit", "m");
  file.write("/points/position", flatten(p.position), {n, 3});
  file.write("/points/volume", p.volume, {n});
  file.write("/points/body", p.body, {n});
  file.write("/points/half_size", flatten(p.half_size), {n, 3});
  if (!p.domain_vertices.empty()) {
    std::vector<double> flat;
    flat.reserve(24 * n);
    for (const auto& hex : p.domain_vertices)
      for (const auto& v : hex) flat.insert(flat.end(), {v.x(), v.y(), v.z()});
    file.write("/points/domain_vertices", flat, {n, 8, 3});
  }
  file.write_strings("/points/body_names", p.body_names);
  std::vector<std::string> tag_names;
  for (const auto& [name, mask] : p.tags) {
    tag_names.push_back(name);
    file.write("/points/tags/" + name, mask, {mask.size()});
  }
  file.write_strings("/points/tag_names", tag_names);
  std::vector<std::string> keys, values;
  for (const auto& [k, v] : p.parameters) {
    keys.push_back(k);
    values.push_back(v);
  }
  file.write_strings("/points/parameters/keys", keys);
  file.write_strings("/points/parameters/values", values);
}

PointSet read_point_set(const Hdf5File& file) {
  if (!holds_point_set(file)) throw InputError(file.path(), "/points", "not a latmpm point-set file");
  PointSet p;
  p.cell_size = file.double_attribute("/points", "cell_size");
  p.ppc = static_cast<int>(file.int_attribute("/points", "ppc"));
  p.position = unflatten(file, "/points/position");
  p.volume = file.read_doubles("/points/volume");
  p.body = file.read_int32("/points/body");
  p.half_size = unflatten(file, "/points/half_size");
  p.body_names = file.read_strings("/points/body_names");
  if (file.exists("/points/domain_vertices")) {  // optional: CPDI1 hexahedra (latmpm-hexmesh)
    std::vector<size_t> dims;
    const auto flat = file.read_doubles("/points/domain_vertices", &dims);
    if (dims.size() != 3 || dims[1] != 8 || dims[2] != 3)
      throw InputError(file.path(), "/points/domain_vertices", "expected an N×8×3 array");
    p.domain_vertices.resize(dims[0]);
    for (size_t i = 0; i < dims[0]; ++i)
      for (size_t a = 0; a < 8; ++a)
        p.domain_vertices[i][a] = {flat[24 * i + 3 * a], flat[24 * i + 3 * a + 1], flat[24 * i + 3 * a + 2]};
  }
  for (const auto& name : file.read_strings("/points/tag_names"))
    p.tags[name] = file.read_uint8("/points/tags/" + name);
  if (file.exists("/points/parameters/keys")) {
    auto keys = file.read_strings("/points/parameters/keys");
    auto values = file.read_strings("/points/parameters/values");
    if (keys.size() != values.size())
      throw InputError(file.path(), "/points/parameters", "keys and values differ in length");
    for (size_t i = 0; i < keys.size(); ++i) p.parameters[keys[i]] = values[i];
  }
  p.validate(file.path());
  return p;
}

}  // namespace latmpm
