#include "scene/scene_points.hpp"

#include "core/errors.hpp"
#include "core/hdf5_file.hpp"
#include "core/provenance.hpp"
#include "core/text.hpp"

namespace latmpm {
namespace {

// Whether the scene keeps a point of its body `body` at x: not beyond the body's trim plane.
bool kept_by_trim(const BodySpec& body, const Eigen::Vector3d& x) {
  return body.trim_normal.isZero() || (x - body.trim_point).dot(body.trim_normal) <= 0;
}

// Appends the points of `part` that the scene simulates to `all`, renumbering their bodies
// into the scene's order (body_map: -1 for an omitted body, whose points are dropped, as are
// those beyond their body's trim plane).
void append(PointSet& all, const PointSet& part, const std::vector<int32_t>& body_map, const Scene& scene) {
  const size_t before = all.size();
  std::vector<size_t> kept;
  for (size_t p = 0; p < part.size(); ++p) {
    const int32_t b = body_map[part.body[p]];
    if (b >= 0 && kept_by_trim(scene.bodies[size_t(b)], part.position[p])) kept.push_back(p);
  }
  // CPDI1 domains survive the merge only while every file has them (a cpdi1 run needs them
  // for every point and says so when they are missing).
  const bool domains = all.domain_vertices.size() == before && part.domain_vertices.size() == part.size();
  if (!domains) all.domain_vertices.clear();
  for (size_t p : kept) {
    all.position.push_back(part.position[p]);
    all.volume.push_back(part.volume[p]);
    all.half_size.push_back(part.half_size[p]);
    if (domains) all.domain_vertices.push_back(part.domain_vertices[p]);
    all.body.push_back(body_map[part.body[p]]);
  }
  for (auto& [name, mask] : all.tags) mask.resize(before + kept.size(), 0);
  for (const auto& [name, mask] : part.tags) {
    auto& merged = all.tags[name];
    merged.resize(before, 0);
    for (size_t p : kept) merged.push_back(mask[p]);
  }
  for (const auto& [key, value] : part.parameters) all.parameters.emplace(key, value);
}

int omitted_index(const Scene& scene, const std::string& name) {
  for (size_t b = 0; b < scene.omitted_bodies.size(); ++b)
    if (scene.omitted_bodies[b].name == name) return int(b);
  return -1;
}

}  // namespace

PointSet load_scene_points(const Scene& scene, Provenance* provenance) {
  PointSet all;
  for (const auto& body : scene.bodies) all.body_names.push_back(body.name);
  std::vector<bool> has_points(scene.bodies.size(), false);
  std::vector<bool> has_omitted_points(scene.omitted_bodies.size(), false);
  std::vector<std::string> names_in_files;

  for (size_t f = 0; f < scene.point_files.size(); ++f) {
    const PointFileSpec& spec = scene.point_files[f];
    const std::string field = "points." + std::to_string(f) + ".file";
    Hdf5File file(spec.path, Hdf5File::Mode::read);
    if (!holds_point_set(file))
      throw InputError(spec.where, field, "'" + spec.path + "' is not a point-set file (latmpm-voxelize writes them)");
    PointSet part = read_point_set(file);
    part.validate(spec.path);
    if (provenance) {
      provenance->inputs.push_back(spec.path);
      provenance->inherit_from(file);
    }
    std::vector<size_t> count(part.body_names.size(), 0);
    for (int32_t b : part.body) ++count[b];
    std::vector<int32_t> body_map(part.body_names.size(), -1);
    for (size_t b = 0; b < part.body_names.size(); ++b) {
      const std::string& name = part.body_names[b];
      names_in_files.push_back(name);
      int index = all.body_index(name);
      const bool omitted = omitted_index(scene, name) >= 0;
      if (omitted && count[b] > 0) has_omitted_points[size_t(omitted_index(scene, name))] = true;
      if (index < 0 && !omitted && count[b] > 0)
        throw InputError(spec.where, field,
                         "'" + spec.path + "' holds body '" + name + "' (" + std::to_string(count[b]) +
                             " points) which the scene does not describe; add [bodies." + name + "]");
      body_map[b] = index;
      if (index >= 0 && count[b] > 0) has_points[index] = true;
    }
    if (f == 0) {
      all.cell_size = part.cell_size;
      all.ppc = part.ppc;
    }
    append(all, part, body_map, scene);
  }
  for (size_t b = 0; b < scene.bodies.size(); ++b)
    if (!has_points[b])
      throw InputError(scene.bodies[b].where, "bodies." + scene.bodies[b].name,
                       "no point file holds a body named '" + scene.bodies[b].name +
                           "' (the files hold: " + listed_or_none(names_in_files) + ")");
  for (size_t b = 0; b < scene.omitted_bodies.size(); ++b)
    if (!has_omitted_points[b])
      throw InputError(scene.omitted_bodies[b].where, "bodies." + scene.omitted_bodies[b].name,
                       "no point file holds a body named '" + scene.omitted_bodies[b].name +
                           "' to omit (the files hold: " + listed_or_none(names_in_files) + ")");
  // A held layer must exist: a misspelt tag would otherwise leave the body free.
  for (size_t b = 0; b < scene.bodies.size(); ++b) {
    const BodySpec& body = scene.bodies[b];
    if (body.hold_tag.empty()) continue;
    const auto tag = all.tags.find(body.hold_tag);
    bool any = false;
    if (tag != all.tags.end())
      for (size_t p = 0; p < all.size() && !any; ++p) any = all.body[p] == int32_t(b) && tag->second[p];
    if (!any) {
      std::vector<std::string> tags;  // std::map: in name order
      for (const auto& [name, mask] : all.tags) tags.push_back(name);
      throw InputError(body.hold_where, "bodies." + body.name + ".hold.tag",
                       "no point of body '" + body.name + "' carries the tag '" + body.hold_tag +
                           "' (the point files' tags: " + listed_or_none(tags) + ")");
    }
  }
  // A record layer the scene names must exist: a misspelt tag would record a load of 0.
  if (!scene.record_where.empty() && !scene.settings.record_tag.empty()) {
    const auto tag = all.tags.find(scene.settings.record_tag);
    bool any = false;
    if (tag != all.tags.end())
      for (size_t p = 0; p < all.size() && !any; ++p) any = tag->second[p];
    if (!any) {
      std::vector<std::string> tags;
      for (const auto& [name, mask] : all.tags) tags.push_back(name);
      throw InputError(scene.record_where, "output.record_tag",
                       "no point carries the tag '" + scene.settings.record_tag + "' (the point files' tags: " +
                           listed_or_none(tags) + ")");
    }
  }
  return all;
}

}  // namespace latmpm
