#include "mesh/mesh_repair.hpp"

#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_mesh_to_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/stitch_borders.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

#include <cmath>
#include <iterator>
#include <map>

#include "mesh/box_face_caps.hpp"
#include "mesh/cgal_surface.hpp"
#include "mesh/vertex_weld.hpp"

namespace latmpm {
namespace {

using cgal::Point;
using cgal::Surface;
namespace PMP = CGAL::Polygon_mesh_processing;

std::string plural(size_t n, const std::string& word) {
  return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

// Fills each border cycle of at most `max_edges` edges; returns the cycles left open.
size_t fill_small_holes(Surface& surface, size_t max_edges, RepairReport& report) {
  std::vector<Surface::Halfedge_index> cycles;
  PMP::extract_boundary_cycles(surface, std::back_inserter(cycles));
  size_t left = 0;
  for (auto h : cycles) {
    size_t edges = 0;
    for (auto hc : CGAL::halfedges_around_face(h, surface)) {
      (void)hc;
      ++edges;
    }
    if (edges > max_edges) {
      ++left;
      continue;
    }
    std::vector<Surface::Face_index> added;
    PMP::triangulate_hole(surface, h, std::back_inserter(added));
    if (added.empty()) {
      ++left;
      continue;
    }
    ++report.holes_filled;
    report.hole_faces_added += added.size();
    for (auto f : added) report.filled_area += PMP::face_area(f, surface);
  }
  return left;
}

// Six times the signed volume enclosed by each connected component (divergence theorem).
std::vector<double> component_volumes(const Surface& surface,
                                      const Surface::Property_map<Surface::Face_index, size_t>& component,
                                      size_t count) {
  std::vector<double> six_volume(count, 0.0);
  for (auto f : surface.faces()) {
    auto h = surface.halfedge(f);
    const Point& a = surface.point(surface.target(surface.prev(h)));
    const Point& b = surface.point(surface.target(h));
    const Point& c = surface.point(surface.target(surface.next(h)));
    six_volume[component[f]] += CGAL::scalar_product(
        a - CGAL::ORIGIN, CGAL::cross_product(b - CGAL::ORIGIN, c - CGAL::ORIGIN));
  }
  return six_volume;
}

// Makes every closed component face outward. Without self-intersections CGAL decides with
// nesting taken into account (a hollow part's inner shell faces inward); a self-intersecting
// union of parts (struts exported one by one) has each component turned to positive volume.
void orient_outward(Surface& surface, RepairReport& report) {
  if (!CGAL::is_closed(surface)) return;
  auto component = surface.add_property_map<Surface::Face_index, size_t>("f:component", 0).first;
  const size_t count = PMP::connected_components(surface, component);
  const std::vector<double> before = component_volumes(surface, component, count);
  if (!PMP::does_self_intersect<CGAL::Parallel_if_available_tag>(surface)) {
    PMP::orient_to_bound_a_volume(surface);
  } else {
    std::vector<Surface::Face_index> to_flip;
    for (auto f : surface.faces())
      if (before[component[f]] < 0) to_flip.push_back(f);
    if (!to_flip.empty()) PMP::reverse_face_orientations(to_flip, surface);
  }
  const std::vector<double> after = component_volumes(surface, component, count);
  for (size_t c = 0; c < count; ++c) report.components_reversed += (before[c] < 0) != (after[c] < 0);
  surface.remove_property_map(component);
}

}  // namespace

RepairReport repair_mesh(TriangleMesh& mesh, const RepairOptions& options) {
  RepairReport report;
  std::vector<Point> points;
  points.reserve(mesh.vertices.size());
  for (const auto& v : mesh.vertices) points.emplace_back(v.x(), v.y(), v.z());

  // 1. Degenerate faces (repeated vertex or collinear corners) carry no area: drop them.
  std::vector<std::vector<size_t>> polygons;
  polygons.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    const bool degenerate = t[0] == t[1] || t[1] == t[2] || t[0] == t[2] ||
                            CGAL::collinear(points[t[0]], points[t[1]], points[t[2]]);
    if (degenerate) {
      ++report.degenerate_faces_removed;
      continue;
    }
    polygons.push_back({size_t(t[0]), size_t(t[1]), size_t(t[2])});
  }
  if (report.degenerate_faces_removed)
    report.actions.push_back("removed " + plural(report.degenerate_faces_removed, "degenerate face"));

  // 2. CGAL soup repair: merges duplicate points and duplicate faces (either orientation).
  const size_t points_before = points.size(), faces_before = polygons.size();
  PMP::repair_polygon_soup(points, polygons);
  report.duplicate_faces_removed = faces_before - polygons.size();
  report.points_merged = points_before > points.size() ? points_before - points.size() : 0;
  if (report.duplicate_faces_removed)
    report.actions.push_back("removed " + plural(report.duplicate_faces_removed, "duplicate face"));
  if (report.points_merged)
    report.actions.push_back("merged or dropped " + plural(report.points_merged, "unused or duplicate point"));

  // 3. Consistent orientation; non-manifold vertices are split so the soup becomes a mesh.
  const size_t points_before_orient = points.size();
  PMP::orient_polygon_soup(points, polygons);
  report.vertices_split = points.size() - points_before_orient;
  if (report.vertices_split)
    report.actions.push_back("split " + plural(report.vertices_split, "non-manifold vertex") +
                             " to orient the faces");
  Surface surface;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, surface);

  // 4. Borders that coincide (a seam left open by the export) are stitched together.
  report.edges_stitched = PMP::stitch_borders(surface);
  if (report.edges_stitched) report.actions.push_back("stitched " + plural(report.edges_stitched, "border edge pair"));

  // 5. Openings in the bounding box's face planes get planar caps (a part clipped at its
  //    box), the tolerance that of the weld (vertex_weld.hpp); other small holes are
  //    triangulated.
  {
    CGAL::Bbox_3 box;
    for (const Point& p : points) box += p.bbox();
    const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                      CGAL::square(box.zmax() - box.zmin()));
    const CapReport caps = cap_box_face_openings(surface, default_weld_fraction * diagonal);
    report.loops_capped = caps.loops_capped;
    report.cap_faces_added = caps.faces_added;
    report.cap_area = caps.area;
    if (caps.loops_capped)
      report.actions.push_back("capped " + plural(caps.loops_capped, "opening") + " on the bounding box's faces with " +
                               plural(caps.faces_added, "triangle"));
  }
  report.holes_left = fill_small_holes(surface, options.max_hole_edges, report);
  if (report.holes_filled)
    report.actions.push_back("filled " + plural(report.holes_filled, "hole") + " with " +
                             plural(report.hole_faces_added, "triangle"));
  if (report.holes_left)
    report.actions.push_back("left " + plural(report.holes_left, "hole") + " open (more than " +
                             std::to_string(options.max_hole_edges) + " border edges)");

  // 6. Outward orientation of every closed component.
  orient_outward(surface, report);
  if (report.components_reversed)
    report.actions.push_back("turned " + plural(report.components_reversed, "component") + " outward");

  report.surface_area = PMP::area(surface);

  // Back to the plain mesh.
  std::vector<Point> out_points;
  std::vector<std::vector<size_t>> out_polygons;
  PMP::polygon_mesh_to_polygon_soup(surface, out_points, out_polygons);
  mesh.vertices.clear();
  mesh.triangles.clear();
  for (const auto& p : out_points) mesh.vertices.emplace_back(p.x(), p.y(), p.z());
  for (const auto& poly : out_polygons)
    mesh.triangles.push_back({int32_t(poly[0]), int32_t(poly[1]), int32_t(poly[2])});
  if (report.actions.empty()) report.actions.push_back("nothing to repair");
  return report;
}

}  // namespace latmpm
