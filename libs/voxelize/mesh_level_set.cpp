#include "voxelize/mesh_level_set.hpp"

#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/util/NullInterrupter.h>

#include <cmath>
#include <vector>

#include "core/errors.hpp"

namespace latmpm {
namespace {

// Forwards OpenVDB's percent reports (when it gives one) to a progress callback.
class ProgressInterrupter : public openvdb::util::NullInterrupter {
 public:
  explicit ProgressInterrupter(const std::function<void(double)>& progress) : progress_(progress) {}
  bool wasInterrupted(int percent = -1) override {
    if (progress_ && percent >= 0) progress_(percent / 100.0);
    return false;
  }

 private:
  const std::function<void(double)>& progress_;
};

}  // namespace

openvdb::FloatGrid::Ptr mesh_level_set(const TriangleMesh& mesh, double voxel_size_m,
                                       double half_width_voxels,
                                       const std::function<void(double)>& progress) {
  if (!(voxel_size_m > 0) || !std::isfinite(voxel_size_m))
    throw InputError("voxelize", "voxel size", "must be positive");
  if (!(half_width_voxels >= 1)) throw InputError("voxelize", "band half-width", "must be at least 1 voxel");
  openvdb::initialize();
  const auto xform = openvdb::math::Transform::createLinearTransform(voxel_size_m);
  std::vector<openvdb::Vec3s> points;
  points.reserve(mesh.vertices.size());
  for (const auto& v : mesh.vertices)
    points.emplace_back(static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z()));
  std::vector<openvdb::Vec3I> triangles;
  triangles.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) triangles.emplace_back(t[0], t[1], t[2]);
  std::vector<openvdb::Vec4I> no_quads;
  ProgressInterrupter interrupter(progress);
  auto grid = openvdb::tools::meshToLevelSet<openvdb::FloatGrid>(
      interrupter, *xform, points, triangles, no_quads, static_cast<float>(half_width_voxels));
  if (progress) progress(1.0);
  return grid;
}

}  // namespace latmpm
