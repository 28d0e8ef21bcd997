#include "mesh/vertex_weld.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <unordered_map>
#include <vector>

#include "core/disjoint_sets.hpp"

namespace latmpm {
namespace {

struct CellHash {
  size_t operator()(const Eigen::Vector3i& c) const {
    uint64_t h = uint32_t(c.x());
    h = h * 0x9E3779B97F4A7C15ull ^ uint32_t(c.y());
    h = h * 0x9E3779B97F4A7C15ull ^ uint32_t(c.z());
    return size_t(h ^ (h >> 29));
  }
};

}  // namespace

WeldReport weld_nearby_vertices(TriangleMesh& mesh, double relative_tolerance) {
  WeldReport report;
  if (mesh.vertices.size() < 2) return report;
  Eigen::AlignedBox3d box;
  for (const auto& v : mesh.vertices) box.extend(v);
  const double tol = relative_tolerance * box.diagonal().norm();
  report.tolerance = tol;
  // Cell indices below stay within int for tolerances above 1e-9 of the diagonal.
  if (!(tol > 0) || !std::isfinite(tol) || !(relative_tolerance >= 1e-9)) return report;

  // Vertices hashed into cells of edge `tol`: a pair closer than tol lies in neighbouring cells.
  std::unordered_map<Eigen::Vector3i, std::vector<int32_t>, CellHash> cells;
  auto cell_of = [&](const Eigen::Vector3d& v) {
    const Eigen::Vector3d c = ((v - box.min()) / tol).array().floor();
    return Eigen::Vector3i(int(c.x()), int(c.y()), int(c.z()));
  };
  const auto n = static_cast<int32_t>(mesh.vertices.size());
  for (int32_t v = 0; v < n; ++v) cells[cell_of(mesh.vertices[v])].push_back(v);
  DisjointSets<int32_t> clusters(mesh.vertices.size());
  const double tol2 = tol * tol;
  for (int32_t v = 0; v < n; ++v) {
    const Eigen::Vector3i c = cell_of(mesh.vertices[v]);
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          auto it = cells.find(c + Eigen::Vector3i(dx, dy, dz));
          if (it == cells.end()) continue;
          for (int32_t w : it->second)
            if (w > v && (mesh.vertices[w] - mesh.vertices[v]).squaredNorm() <= tol2) clusters.join(v, w);
        }
  }

  // Renumber: representatives keep their position, in their original order.
  std::vector<int32_t> new_index(mesh.vertices.size(), -1);
  std::vector<Eigen::Vector3d> kept;
  for (int32_t v = 0; v < n; ++v) {
    const int32_t r = clusters.find(v);
    if (r == v) {
      new_index[v] = static_cast<int32_t>(kept.size());
      kept.push_back(mesh.vertices[v]);
    } else {
      ++report.vertices_welded;
      report.largest_gap = std::max(report.largest_gap, (mesh.vertices[v] - mesh.vertices[r]).norm());
    }
  }
  if (report.vertices_welded == 0) return report;
  for (int32_t v = 0; v < n; ++v) new_index[v] = new_index[clusters.find(v)];
  for (auto& t : mesh.triangles)
    for (auto& i : t) i = new_index[i];
  mesh.vertices.swap(kept);
  return report;
}

std::string describe(const WeldReport& r) {
  if (r.vertices_welded == 0) return "";
  char text[160];
  std::snprintf(text, sizeof text, "welded %zu vertices closer than %.3g mm (largest gap %.3g mm)",
                r.vertices_welded, r.tolerance * 1e3, r.largest_gap * 1e3);
  return text;
}

}  // namespace latmpm
