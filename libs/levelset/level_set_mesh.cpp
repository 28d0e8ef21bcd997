#include "levelset/level_set_mesh.hpp"

#include <openvdb/tools/LevelSetMeasure.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <cmath>

#include "levelset/level_set_units.hpp"

namespace latmpm {

TriangleMesh level_set_to_mesh(const openvdb::FloatGrid& level_set) {
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(level_set, points, triangles, quads, /*isovalue=*/0.0,
                               /*adaptivity=*/0.0, /*relaxDisorientedTriangles=*/true);
  TriangleMesh mesh;
  mesh.vertices.reserve(points.size());
  for (const auto& p : points)
    mesh.vertices.push_back(Eigen::Vector3d(p.x(), p.y(), p.z()) / grid_units_per_metre);
  mesh.triangles.reserve(triangles.size() + 2 * quads.size());
  // volumeToMesh orders polygons clockwise seen from outside (for a level set, negative
  // inside); we store counter-clockwise, so every polygon is reversed.
  for (const auto& t : triangles) mesh.triangles.push_back({int32_t(t[2]), int32_t(t[1]), int32_t(t[0])});
  for (const auto& q : quads) {
    const auto& v = mesh.vertices;
    // Split along the shorter diagonal: better-shaped triangles.
    if ((v[q[0]] - v[q[2]]).squaredNorm() <= (v[q[1]] - v[q[3]]).squaredNorm()) {
      mesh.triangles.push_back({int32_t(q[2]), int32_t(q[1]), int32_t(q[0])});
      mesh.triangles.push_back({int32_t(q[3]), int32_t(q[2]), int32_t(q[0])});
    } else {
      mesh.triangles.push_back({int32_t(q[3]), int32_t(q[1]), int32_t(q[0])});
      mesh.triangles.push_back({int32_t(q[3]), int32_t(q[2]), int32_t(q[1])});
    }
  }
  return mesh;
}

double level_set_volume(const openvdb::FloatGrid& level_set) {
  return openvdb::tools::levelSetVolume(level_set) / std::pow(grid_units_per_metre, 3);
}

}  // namespace latmpm
