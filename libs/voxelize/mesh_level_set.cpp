#include "voxelize/mesh_level_set.hpp"

#include <openvdb/tools/Composite.h>
#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/util/NullInterrupter.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "core/errors.hpp"
#include "levelset/level_set_units.hpp"
#include "mesh/mesh_checks.hpp"

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

namespace {

openvdb::FloatGrid::Ptr shells_level_set(const TriangleMesh& mesh, const std::vector<int32_t>& shell,
                                         const std::vector<char>& take, const openvdb::math::Transform& xform,
                                         float half_width, float interior_half_width,
                                         openvdb::util::NullInterrupter& interrupter) {
  // The adapter takes index-space points (meshToLevelSet converts them itself).
  std::vector<openvdb::Vec3s> points;
  points.reserve(mesh.vertices.size());
  for (const auto& v : mesh.vertices)
    points.emplace_back(xform.worldToIndex(openvdb::Vec3d(v.x(), v.y(), v.z()) * grid_units_per_metre));
  std::vector<openvdb::Vec3I> triangles;
  triangles.reserve(mesh.triangles.size());
  for (size_t f = 0; f < mesh.triangles.size(); ++f)
    if (take[size_t(shell[f])]) triangles.emplace_back(mesh.triangles[f][0], mesh.triangles[f][1], mesh.triangles[f][2]);
  const openvdb::tools::QuadAndTriangleDataAdapter<openvdb::Vec3s, openvdb::Vec3I> adapter(points, triangles);
  return openvdb::tools::meshToVolume<openvdb::FloatGrid>(interrupter, adapter, xform, half_width, interior_half_width);
}

}  // namespace

openvdb::FloatGrid::Ptr mesh_level_set(const TriangleMesh& mesh, double voxel_size_m,
                                       double half_width_voxels,
                                       const std::function<void(double)>& progress,
                                       double interior_half_width_voxels) {
  if (!(voxel_size_m >= smallest_voxel_m) || !std::isfinite(voxel_size_m))
    throw InputError("voxelize", "voxel size", "must be at least 0.1 um");
  if (!(half_width_voxels >= 1)) throw InputError("voxelize", "band half-width", "must be at least 1 voxel");
  openvdb::initialize();
  const auto xform = level_set_transform(voxel_size_m);
  ProgressInterrupter interrupter(progress);
  const auto half_width = static_cast<float>(half_width_voxels);
  const auto interior_half_width = static_cast<float>(std::max(half_width_voxels, interior_half_width_voxels));

  // meshToLevelSet decides inside and outside by flood fill from the outside, so a cavity
  // (an inner shell facing inward) would come out solid. Shells are therefore taken in
  // order of decreasing |volume| — a shell can only lie inside a larger one — in runs of
  // equal orientation: a run facing like the whole is added (union), a run facing the other
  // way is cut out (difference). A hollow cube is two runs; a part of many separate or
  // overlapping outward shells is one run, one meshToLevelSet call.
  std::vector<int32_t> shell;
  const size_t shells = shell_of_triangles(mesh, shell);
  const std::vector<double> volume = shell_volumes(mesh, shell, shells);
  double total = 0;
  for (double v : volume) total += v;
  std::vector<size_t> order(shells);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return std::fabs(volume[a]) > std::fabs(volume[b]); });
  auto is_cavity = [&](size_t s) { return (volume[s] > 0) != (total > 0) && volume[s] != 0; };
  openvdb::FloatGrid::Ptr grid;
  for (size_t first = 0; first < shells;) {
    size_t last = first;
    while (last < shells && is_cavity(order[last]) == is_cavity(order[first])) ++last;
    std::vector<char> take(shells, 0);
    for (size_t i = first; i < last; ++i) take[order[i]] = 1;
    auto part = shells_level_set(mesh, shell, take, *xform, half_width, interior_half_width, interrupter);
    if (!grid) grid = part;
    else if (is_cavity(order[first])) openvdb::tools::csgDifference(*grid, *part);
    else openvdb::tools::csgUnion(*grid, *part);
    first = last;
  }
  if (!grid) grid = openvdb::FloatGrid::create(float(half_width_voxels * voxel_size_m * grid_units_per_metre));
  if (progress) progress(1.0);
  return grid;
}

}  // namespace latmpm
