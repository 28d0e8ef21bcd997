#include "voxelize/voxelize.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/errors.hpp"
#include "levelset/level_set_mesh.hpp"
#include "levelset/strut_level_set.hpp"
#include "mesh/mesh_checks.hpp"
#include "voxelize/level_set_sampling.hpp"
#include "voxelize/mesh_level_set.hpp"
#include "voxelize/point_regions.hpp"
#include "voxelize/strut_partition.hpp"

namespace latmpm {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

void check_options(const VoxelizeOptions& o) {
  if (!(o.cell_size > 0) || !std::isfinite(o.cell_size))
    throw InputError("voxelize", "cell size", "must be positive");
  if (o.ppc < 1) throw InputError("voxelize", "ppc", "must be at least 1");
  if (!(o.voxel_size >= 0) || !std::isfinite(o.voxel_size))
    throw InputError("voxelize", "voxel size", "must be positive");
}

std::function<void(double)> stage_progress(const VoxelizeOptions& o, const std::string& stage) {
  if (!o.progress) return {};
  return [&o, stage](double fraction) { o.progress(stage, fraction); };
}

// Samples the level set and fills in what both entry points share.
void sample_into(Voxelized& out, const openvdb::FloatGrid& level_set, const VoxelizeOptions& o) {
  out.voxel_size = o.resolved_voxel_size();
  out.active_voxels = level_set.activeVoxelCount();
  const auto start = Clock::now();
  SamplingOptions sampling;
  sampling.cell_size = o.cell_size;
  sampling.ppc = o.ppc;
  sampling.curvature_correction = o.curvature_correction;
  SamplingStats stats;
  out.points = sample_level_set(level_set, sampling, stage_progress(o, "points"), &stats);
  out.dropped_volume = stats.dropped_volume;
  out.sampling_seconds = seconds_since(start);
}

}  // namespace

double VoxelizeOptions::band_half_width() const {
  return std::max(3.0, 0.5 * spacing() / resolved_voxel_size() + std::sqrt(3.0) + 0.05);
}

double VoxelizeOptions::interior_band_half_width() const {
  return std::max(band_half_width(), cell_size / resolved_voxel_size() + 2.5);
}

Voxelized voxelize_strut_graph(const StrutGraph& graph, const VoxelizeOptions& options) {
  check_options(options);
  Voxelized out;
  const auto start = Clock::now();
  const auto level_set = strut_graph_level_set(graph, options.resolved_voxel_size(),
                                               options.band_half_width(),
                                               stage_progress(options, "level set"));
  out.level_set_seconds = seconds_since(start);
  sample_into(out, *level_set, options);
  out.solid_volume = level_set_volume(*level_set);
  assign_strut_graph_bodies(out.points, graph);
  std::vector<std::string> plate_names;
  for (const Plate& p : graph.plates) plate_names.push_back(p.name);
  tag_regions(out.points, plate_names);
  out.points.parameters = graph.parameters;
  if (options.strut_groups > 0) tag_strut_groups(out.points, graph, partition_struts(graph, options.strut_groups));
  return out;
}

Voxelized voxelize_mesh(const TriangleMesh& mesh, const std::string& body_name,
                        const VoxelizeOptions& options) {
  check_options(options);
  Voxelized out;
  const auto start = Clock::now();
  const auto level_set = mesh_level_set(mesh, options.resolved_voxel_size(), options.band_half_width(),
                                        stage_progress(options, "level set"), options.interior_band_half_width());
  out.level_set_seconds = seconds_since(start);
  sample_into(out, *level_set, options);
  out.thin = find_thin_features(*level_set, 2 * options.cell_size);
  out.solid_volume = std::fabs(signed_volume(mesh));
  out.points.body_names = {body_name};
  tag_regions(out.points, {});
  return out;
}

}  // namespace latmpm
