#include "mesh/box_face_caps.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <array>
#include <cmath>
#include <iterator>
#include <list>
#include <map>
#include <vector>

namespace latmpm {
namespace {

using cgal::Kernel;
using cgal::Surface;
namespace PMP = CGAL::Polygon_mesh_processing;

struct FaceInfo {
  int nesting = -1;  // loops crossed from the outside; odd = inside a cap
  int domain = -1;   // connected inside region
};
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<Surface::Vertex_index, Kernel>;
using FaceBase = CGAL::Constrained_triangulation_face_base_2<
    Kernel, CGAL::Triangulation_face_base_with_info_2<FaceInfo, Kernel>>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;

// The plane of a box face: coordinate `axis` equal to `value`.
struct BoxFace {
  int axis;
  bool upper;
  bool operator<(const BoxFace& o) const { return axis != o.axis ? axis < o.axis : upper < o.upper; }
};

// Nesting levels by flood fill from the infinite face, each constraint crossed adding one
// (the polygon-with-holes recipe of CGAL's Triangulation_2 manual).
void mark_nesting(Cdt& cdt) {
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info().nesting = -1;
  std::list<Cdt::Edge> border;
  auto flood = [&](Cdt::Face_handle start, int level) {
    if (start->info().nesting != -1) return;
    std::list<Cdt::Face_handle> queue{start};
    while (!queue.empty()) {
      Cdt::Face_handle f = queue.front();
      queue.pop_front();
      if (f->info().nesting != -1) continue;
      f->info().nesting = level;
      for (int i = 0; i < 3; ++i) {
        Cdt::Face_handle n = f->neighbor(i);
        if (n->info().nesting != -1) continue;
        if (cdt.is_constrained(Cdt::Edge(f, i))) border.push_back(Cdt::Edge(f, i));
        else queue.push_back(n);
      }
    }
  };
  flood(cdt.infinite_face(), 0);
  while (!border.empty()) {
    const Cdt::Edge e = border.front();
    border.pop_front();
    Cdt::Face_handle n = e.first->neighbor(e.second);
    if (n->info().nesting == -1) flood(n, e.first->info().nesting + 1);
  }
}

// Caps the loops of one box face; returns false (adding nothing) if they cannot be.
bool cap_face(Surface& surface, const BoxFace& plane, const std::vector<Surface::Halfedge_index>& loops,
              CapReport& report) {
  const int u = (plane.axis + 1) % 3, v = (plane.axis + 2) % 3;
  Cdt cdt;
  size_t inserted = 0;
  for (auto h : loops) {
    std::vector<Cdt::Vertex_handle> ring;
    for (auto hc : CGAL::halfedges_around_face(h, surface)) {
      const auto& p = surface.point(surface.target(hc));
      const std::array<double, 3> xyz{p.x(), p.y(), p.z()};
      Cdt::Vertex_handle vh = cdt.insert(Cdt::Point(xyz[u], xyz[v]));
      if (vh->info() != Surface::Vertex_index() && vh->info() != surface.target(hc)) return false;  // two vertices at one spot
      if (vh->info() == Surface::Vertex_index()) ++inserted;
      vh->info() = surface.target(hc);
      ring.push_back(vh);
    }
    for (size_t i = 0; i < ring.size(); ++i) cdt.insert_constraint(ring[i], ring[(i + 1) % ring.size()]);
  }
  if (cdt.number_of_vertices() != inserted) return false;  // crossing loops made new points
  mark_nesting(cdt);

  // Inside regions, each with the orientation its loops' border halfedges demand: a cap
  // face must run along a border halfedge in the halfedge's direction.
  std::vector<std::vector<Cdt::Face_handle>> domains;
  std::vector<int> flip;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (f->info().nesting % 2 == 0 || f->info().domain >= 0) continue;
    const int d = static_cast<int>(domains.size());
    domains.emplace_back();
    flip.push_back(-1);
    std::vector<Cdt::Face_handle> stack{f};
    f->info().domain = d;
    while (!stack.empty()) {
      Cdt::Face_handle g = stack.back();
      stack.pop_back();
      domains[d].push_back(g);
      for (int i = 0; i < 3; ++i) {
        if (cdt.is_constrained(Cdt::Edge(g, i))) {
          // The face's counter-clockwise edge opposite vertex i runs ccw(i) -> cw(i).
          const auto from = g->vertex(Cdt::ccw(i))->info(), to = g->vertex(Cdt::cw(i))->info();
          const auto forward = surface.halfedge(from, to), backward = surface.halfedge(to, from);
          if (flip[d] < 0 && forward != Surface::null_halfedge() && surface.is_border(forward)) flip[d] = 0;
          if (flip[d] < 0 && backward != Surface::null_halfedge() && surface.is_border(backward)) flip[d] = 1;
          continue;
        }
        Cdt::Face_handle n = g->neighbor(i);
        if (!cdt.is_infinite(n) && n->info().domain < 0 && n->info().nesting % 2 == 1) {
          n->info().domain = d;
          stack.push_back(n);
        }
      }
    }
    if (flip[d] < 0) return false;
  }
  for (size_t d = 0; d < domains.size(); ++d)
    for (Cdt::Face_handle f : domains[d]) {
      auto a = f->vertex(0)->info(), b = f->vertex(1)->info(), c = f->vertex(2)->info();
      if (flip[d]) std::swap(b, c);
      if (surface.add_face(a, b, c) == Surface::null_face()) continue;  // left for the hole filler
      ++report.faces_added;
      const auto& pa = surface.point(a);
      report.area += 0.5 * std::sqrt(CGAL::cross_product(surface.point(b) - pa, surface.point(c) - pa).squared_length());
    }
  report.loops_capped += loops.size();
  return true;
}

}  // namespace

CapReport cap_box_face_openings(Surface& surface, double tolerance) {
  CapReport report;
  if (surface.number_of_vertices() == 0) return report;
  CGAL::Bbox_3 box;
  for (auto v : surface.vertices()) box += surface.point(v).bbox();
  std::vector<Surface::Halfedge_index> cycles;
  PMP::extract_boundary_cycles(surface, std::back_inserter(cycles));
  std::map<BoxFace, std::vector<Surface::Halfedge_index>> by_face;
  for (auto h : cycles) {
    for (int axis = 0; axis < 3; ++axis)
      for (bool upper : {false, true}) {
        const double value = upper ? box.max(axis) : box.min(axis);
        bool on_plane = true;
        for (auto hc : CGAL::halfedges_around_face(h, surface))
          on_plane = on_plane && std::fabs(surface.point(surface.target(hc))[axis] - value) <= tolerance;
        if (on_plane) {
          by_face[{axis, upper}].push_back(h);
          axis = 3;  // a loop belongs to one face
          break;
        }
      }
  }
  for (const auto& [plane, loops] : by_face) cap_face(surface, plane, loops, report);
  return report;
}

}  // namespace latmpm
