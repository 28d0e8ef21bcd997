#include "voxelize/resource_estimate.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "core/errors.hpp"
#include "levelset/level_set_units.hpp"
#include "mesh/mesh_checks.hpp"

namespace latmpm {
namespace {

// Peak bytes per material point: the point set (position, volume, half size, body, tags:
// ~64 B) plus the sampler's working copy (key, position, fraction, φ and the sorted keys:
// ~56 B), rounded up.
constexpr double bytes_per_point = 160;
// Peak bytes per narrow-band voxel: meshToVolume holds a float distance grid, an int32
// closest-triangle grid and a mask; leaves are partly filled.
constexpr double bytes_per_band_voxel = 24;

void finish(ResourceEstimate& e, const VoxelizeOptions& o) {
  const double spacing = o.spacing(), voxel = o.resolved_voxel_size();
  e.points = e.volume / (spacing * spacing * spacing);
  e.band_voxels = e.area / (voxel * voxel) * (o.band_half_width() + o.interior_band_half_width());
  e.bytes = bytes_per_point * e.points + bytes_per_band_voxel * e.band_voxels;
  const double reach = std::max(e.bounds.min().cwiseAbs().maxCoeff(), e.bounds.max().cwiseAbs().maxCoeff());
  e.largest_index = reach / voxel;
}

std::string human_bytes(double bytes) {
  char text[32];
  if (bytes >= 1e12) std::snprintf(text, sizeof text, "%.3g TB", bytes / 1e12);
  else if (bytes >= 1e9) std::snprintf(text, sizeof text, "%.3g GB", bytes / 1e9);
  else std::snprintf(text, sizeof text, "%.3g MB", bytes / 1e6);
  return text;
}

std::string with_hint(const std::string& text, const std::string& hint) {
  return hint.empty() ? text : text + "; " + hint;
}

}  // namespace

ResourceEstimate estimate_resources(const TriangleMesh& mesh, const VoxelizeOptions& options) {
  ResourceEstimate e;
  for (const auto& v : mesh.vertices) e.bounds.extend(v);
  e.volume = std::fabs(signed_volume(mesh));
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.vertices[t[0]];
    e.area += 0.5 * (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a).norm();
  }
  finish(e, options);
  return e;
}

ResourceEstimate estimate_resources(const StrutGraph& graph, const VoxelizeOptions& options) {
  ResourceEstimate e;
  for (const Strut& s : graph.struts) {
    const double r = s.radius, length = (graph.nodes[s.a] - graph.nodes[s.b]).norm();
    e.volume += M_PI * r * r * length + 4.0 / 3.0 * M_PI * r * r * r;
    e.area += 2 * M_PI * r * length + 4 * M_PI * r * r;
    for (const Eigen::Vector3d& n : {graph.nodes[s.a], graph.nodes[s.b]}) {
      e.bounds.extend(n - Eigen::Vector3d::Constant(r));
      e.bounds.extend(n + Eigen::Vector3d::Constant(r));
    }
  }
  for (const Plate& p : graph.plates) {
    const Eigen::Vector3d d = p.max - p.min;
    e.volume += d.prod();
    e.area += 2 * (d.x() * d.y() + d.y() * d.z() + d.z() * d.x());
    e.bounds.extend(p.min);
    e.bounds.extend(p.max);
  }
  finish(e, options);
  return e;
}

void check_resources(const ResourceEstimate& e, const VoxelizeOptions& o, double max_bytes,
                     const std::string& where, const std::string& hint) {
  const std::string extent = "extent " + describe_extent(e.bounds);
  if (o.resolved_voxel_size() < smallest_voxel_m) {
    char text[160];
    std::snprintf(text, sizeof text, "level-set voxel %.3g um (from --cell, --ppc, --voxel) is below the smallest, 0.1 um",
                  o.resolved_voxel_size() * 1e6);
    throw InputError(where, "voxel", text);
  }
  if (!(e.largest_index < max_index_extent)) {
    char text[200];
    std::snprintf(text, sizeof text, "reaches %.3g voxels of %.3g mm from the origin, beyond the %.3g a level set can index; ",
                  e.largest_index, o.resolved_voxel_size() * 1e3, max_index_extent);
    throw InputError(where, "extent", with_hint(text + extent, hint));
  }
  if (!(e.bytes <= max_bytes)) {
    char text[200];
    std::snprintf(text, sizeof text, "needs about %s (%.3g points, %.3g level-set voxels), more than --max-memory %s; ",
                  human_bytes(e.bytes).c_str(), e.points, e.band_voxels, human_bytes(max_bytes).c_str());
    throw InputError(where, "size", with_hint(text + extent + ": use a coarser --cell or a smaller --ppc", hint));
  }
  const double spacing = o.spacing();
  if (e.bounds.sizes().maxCoeff() < spacing) {
    char text[120];
    std::snprintf(text, sizeof text, "smaller than one point spacing (%.3g mm): ", spacing * 1e3);
    throw InputError(where, "extent", with_hint(text + extent, hint));
  }
}

double physical_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page > 0 ? double(pages) * double(page) : INFINITY;
}

double parse_bytes(const std::string& text, const std::string& where) {
  struct Suffix {
    const char* name;
    double bytes;
  };
  const Suffix suffixes[] = {{"TiB", 1099511627776.0}, {"GiB", 1073741824.0}, {"MiB", 1048576.0},
                             {"KiB", 1024.0}, {"TB", 1e12}, {"GB", 1e9}, {"MB", 1e6}, {"kB", 1e3},
                             {"KB", 1e3}, {"B", 1.0}};
  for (const Suffix& s : suffixes) {
    const size_t n = std::strlen(s.name);
    if (text.size() <= n || text.compare(text.size() - n, n, s.name) != 0) continue;
    const std::string number = text.substr(0, text.size() - n);
    char* end = nullptr;
    const double value = std::strtod(number.c_str(), &end);
    if (end == number.c_str() + number.size() && std::isfinite(value) && value > 0) return value * s.bytes;
    break;
  }
  throw InputError(where, "", "'" + text + "' is not a positive amount of memory with a unit (e.g. 16GB, 512MB)");
}

std::string describe_extent(const Eigen::AlignedBox3d& b) {
  char text[256];
  const Eigen::Vector3d lo = b.min() * 1e3, hi = b.max() * 1e3, d = b.sizes() * 1e3;
  std::snprintf(text, sizeof text, "x [%.4g, %.4g] y [%.4g, %.4g] z [%.4g, %.4g] mm (%.4g x %.4g x %.4g mm)",
                lo.x(), hi.x(), lo.y(), hi.y(), lo.z(), hi.z(), d.x(), d.y(), d.z());
  return text;
}

std::string unit_hint(const Eigen::AlignedBox3d& bounds, double metres_per_unit, double spacing) {
  const double size = bounds.sizes().maxCoeff();  // m, as read
  if (!(size > 0) || !std::isfinite(size) || (size >= spacing && size <= 2.0)) return "";
  struct Unit {
    const char* name;
    double metres;
  };
  const Unit units[] = {{"m", 1.0}, {"cm", 1e-2}, {"mm", 1e-3}, {"in", 0.0254}, {"um", 1e-6}};
  const double in_file_units = size / metres_per_unit;
  const Unit* best = nullptr;
  double best_distance = INFINITY;
  for (const Unit& u : units) {
    const double candidate = in_file_units * u.metres;
    if (std::fabs(u.metres / metres_per_unit - 1) < 1e-9 || candidate < 1e-3 || candidate > 2.0) continue;
    const double distance = std::fabs(std::log(candidate / 0.05));  // printed parts: ~5 cm
    if (distance < best_distance) best = &u, best_distance = distance;
  }
  return best ? std::string("did you mean --units ") + best->name + "?" : "";
}

}  // namespace latmpm
