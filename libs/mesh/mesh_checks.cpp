#include "mesh/mesh_checks.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <sstream>
#include <vector>

#include "core/disjoint_sets.hpp"

namespace latmpm {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
namespace PMP = CGAL::Polygon_mesh_processing;

Point to_cgal(const Eigen::Vector3d& v) { return Point(v.x(), v.y(), v.z()); }

bool has_repeated_vertex(const std::array<int32_t, 3>& t) {
  return t[0] == t[1] || t[1] == t[2] || t[0] == t[2];
}

// Classifies every face: degenerate (repeated vertex or exactly collinear corners, by an
// exact predicate) or a duplicate of an earlier face with the same vertex set.
struct FaceFlags {
  std::vector<char> degenerate, duplicate;
};

FaceFlags classify_faces(const TriangleMesh& mesh) {
  const size_t n = mesh.triangles.size();
  FaceFlags flags{std::vector<char>(n, 0), std::vector<char>(n, 0)};
  std::vector<std::pair<std::array<int32_t, 3>, size_t>> sorted(n);
  for (size_t f = 0; f < n; ++f) {
    const auto& t = mesh.triangles[f];
    flags.degenerate[f] = has_repeated_vertex(t) ||
        CGAL::collinear(to_cgal(mesh.vertices[t[0]]), to_cgal(mesh.vertices[t[1]]),
                        to_cgal(mesh.vertices[t[2]]));
    auto key = t;
    std::sort(key.begin(), key.end());
    sorted[f] = {key, f};
  }
  std::sort(sorted.begin(), sorted.end());
  for (size_t i = 1; i < n; ++i)
    if (sorted[i].first == sorted[i - 1].first) flags.duplicate[sorted[i].second] = 1;
  return flags;
}

// Edge incidences from the connectivity: boundary (1 face), non-manifold (> 2), and whether
// each two-face edge is traversed once in each direction (consistent orientation).
void count_edges(const TriangleMesh& mesh, MeshReport& report) {
  struct Incidence {
    int32_t lo, hi;
    bool forward;  // traversed lo -> hi
    bool operator<(const Incidence& o) const { return lo != o.lo ? lo < o.lo : hi < o.hi; }
  };
  std::vector<Incidence> edges;
  edges.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    if (has_repeated_vertex(t)) continue;  // counted as degenerate, has no proper edges
    for (int k = 0; k < 3; ++k) {
      const int32_t a = t[k], b = t[(k + 1) % 3];
      edges.push_back({std::min(a, b), std::max(a, b), a < b});
    }
  }
  std::sort(edges.begin(), edges.end());
  report.consistently_oriented = true;
  for (size_t i = 0; i < edges.size();) {
    size_t j = i;
    while (j < edges.size() && edges[j].lo == edges[i].lo && edges[j].hi == edges[i].hi) ++j;
    const size_t faces = j - i;
    if (faces == 1) ++report.boundary_edges;
    if (faces > 2) ++report.non_manifold_edges;
    if (faces == 2 && edges[i].forward == edges[i + 1].forward) report.consistently_oriented = false;
    i = j;
  }
}

// Pairs of crossing triangles. CGAL's search needs a halfedge mesh, so the soup (without
// degenerate and duplicate faces) is first made one: orient_polygon_soup duplicates
// non-manifold vertices and flips faces as needed, which changes no triangle's geometry.
size_t count_self_intersections(const TriangleMesh& mesh, const FaceFlags& flags) {
  std::vector<Point> points;
  points.reserve(mesh.vertices.size());
  for (const auto& v : mesh.vertices) points.push_back(to_cgal(v));
  std::vector<std::array<size_t, 3>> polygons;
  polygons.reserve(mesh.triangles.size());
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    if (flags.degenerate[f] || flags.duplicate[f]) continue;
    const auto& t = mesh.triangles[f];
    polygons.push_back({size_t(t[0]), size_t(t[1]), size_t(t[2])});
  }
  if (polygons.size() < 2) return 0;
  PMP::orient_polygon_soup(points, polygons);
  CGAL::Surface_mesh<Point> surface;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, surface);
  using Face = CGAL::Surface_mesh<Point>::Face_index;
  std::vector<std::pair<Face, Face>> pairs;
  PMP::self_intersections<CGAL::Parallel_if_available_tag>(surface, std::back_inserter(pairs));
  return pairs.size();
}

}  // namespace

double signed_volume(const TriangleMesh& mesh) {
  // Divergence theorem: V = Σ_faces a·(b×c)/6, relative to the first vertex to limit
  // cancellation for parts far from the origin.
  if (mesh.vertices.empty()) return 0;
  const Eigen::Vector3d o = mesh.vertices.front();
  double six_v = 0;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d a = mesh.vertices[t[0]] - o, b = mesh.vertices[t[1]] - o,
                          c = mesh.vertices[t[2]] - o;
    six_v += a.dot(b.cross(c));
  }
  return six_v / 6.0;
}

size_t shell_of_triangles(const TriangleMesh& mesh, std::vector<int32_t>& shell) {
  DisjointSets<int32_t> sets(mesh.vertices.size());
  for (const auto& t : mesh.triangles)
    for (int k = 1; k < 3; ++k) sets.join(t[0], t[k]);
  std::vector<int32_t> number(mesh.vertices.size(), -1);
  size_t shells = 0;
  shell.resize(mesh.triangles.size());
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    int32_t& n = number[sets.find(mesh.triangles[f][0])];
    if (n < 0) n = static_cast<int32_t>(shells++);
    shell[f] = n;
  }
  return shells;
}

std::vector<double> shell_volumes(const TriangleMesh& mesh, const std::vector<int32_t>& shell, size_t shells) {
  std::vector<double> six_v(shells, 0.0);
  if (mesh.vertices.empty()) return six_v;
  const Eigen::Vector3d o = mesh.vertices.front();  // as signed_volume: limits cancellation
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    const auto& t = mesh.triangles[f];
    const Eigen::Vector3d a = mesh.vertices[t[0]] - o, b = mesh.vertices[t[1]] - o, c = mesh.vertices[t[2]] - o;
    six_v[size_t(shell[f])] += a.dot(b.cross(c));
  }
  for (double& v : six_v) v /= 6.0;
  return six_v;
}

MeshReport check_mesh(const TriangleMesh& mesh, bool find_self_intersections) {
  MeshReport report;
  report.vertices = mesh.vertices.size();
  report.triangles = mesh.triangles.size();
  const FaceFlags flags = classify_faces(mesh);
  report.degenerate_faces = static_cast<size_t>(std::count(flags.degenerate.begin(), flags.degenerate.end(), 1));
  report.duplicate_faces = static_cast<size_t>(std::count(flags.duplicate.begin(), flags.duplicate.end(), 1));
  count_edges(mesh, report);
  const double v = signed_volume(mesh);
  report.volume = std::fabs(v);
  report.outward = v > 0;
  std::vector<int32_t> shell;
  report.shells = shell_of_triangles(mesh, shell);
  for (double shell_volume : shell_volumes(mesh, shell, report.shells))
    report.cavities += (shell_volume > 0) != (v > 0) && shell_volume != 0;
  if (find_self_intersections) {
    report.self_intersecting_pairs = count_self_intersections(mesh, flags);
    report.self_intersections_searched = true;
  }
  return report;
}

std::string describe(const MeshReport& r) {
  std::ostringstream s;
  s << r.triangles << " triangles, " << r.vertices << " vertices, ";
  if (r.closed()) {
    s << "closed";
  } else {
    s << "NOT closed (" << r.boundary_edges << " boundary edges, " << r.non_manifold_edges
      << " non-manifold edges)";
  }
  s << ", " << (r.consistently_oriented ? "consistently oriented" : "INCONSISTENTLY oriented");
  if (r.closed() && r.consistently_oriented) s << (r.outward ? " outward" : " inward");
  s << ", volume " << r.volume << " m^3, " << r.shells << (r.shells == 1 ? " shell" : " shells");
  if (r.cavities) s << " (" << r.cavities << (r.cavities == 1 ? " cavity" : " cavities") << ")";
  s << "\n  degenerate faces " << r.degenerate_faces << ", duplicate faces " << r.duplicate_faces
    << ", self-intersecting pairs ";
  if (r.self_intersections_searched) s << r.self_intersecting_pairs;
  else s << "not searched";
  s << "\n  verdict: "
    << (r.is_valid_solid()    ? "a valid solid"
        : r.encloses_volume() ? "encloses a volume (defects above are tolerated by the voxelizer)"
                              : "NOT a closed solid");
  return s.str();
}

}  // namespace latmpm
