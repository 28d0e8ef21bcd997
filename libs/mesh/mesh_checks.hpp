// Is a triangle mesh a solid that can be voxelized? Counts what is wrong with it.
// Open boundaries, non-manifold edges, degenerate and duplicate faces and inconsistent
// orientation are found from the connectivity; self-intersections with CGAL (exact
// predicates). meshToLevelSet copes with closed self-intersecting meshes but misclassifies
// inside/outside of open ones (DEBIAN-STACK.md), which is why `closed()` gates voxelizing.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "mesh/triangle_mesh.hpp"

namespace latmpm {

struct MeshReport {
  size_t vertices = 0, triangles = 0;
  size_t boundary_edges = 0;      // edges with exactly one triangle: holes, open borders
  size_t non_manifold_edges = 0;  // edges with more than two triangles
  size_t degenerate_faces = 0;    // repeated vertex or zero area (exactly collinear corners)
  size_t duplicate_faces = 0;     // extra copies of a triangle with the same three vertices
  size_t self_intersecting_pairs = 0;  // pairs of triangles that cross (0 if not searched)
  bool self_intersections_searched = false;
  bool consistently_oriented = false;  // every two-triangle edge is used once each way
  bool outward = false;  // signed volume > 0: counter-clockwise seen from outside
  double volume = 0;     // m³, |signed volume| by the divergence theorem (exact if closed)
  // Shells: connected sets of triangles (sharing vertices). A cavity is a shell whose signed
  // volume has the opposite sign of the whole: an inner surface facing into the void, which
  // is part of a hollow solid (the voxelizer keeps it empty).
  size_t shells = 0, cavities = 0;

  bool closed() const { return triangles > 0 && boundary_edges == 0 && non_manifold_edges == 0; }
  // A closed, consistently oriented surface that encloses volume: meshToLevelSet classifies
  // inside and outside of such a mesh correctly, self-intersecting or not.
  bool encloses_volume() const { return closed() && consistently_oriented && volume > 0; }
  // Strictly valid: also outward, no degenerate or duplicate faces, no self-intersections.
  bool is_valid_solid() const {
    return encloses_volume() && outward && degenerate_faces == 0 && duplicate_faces == 0 &&
           self_intersecting_pairs == 0;
  }
};

// Counts every defect listed above. The self-intersection search (CGAL box intersection,
// parallel with TBB) is the expensive part and can be skipped.
MeshReport check_mesh(const TriangleMesh& mesh, bool find_self_intersections = true);

// Several lines for a human: counts and a verdict, e.g.
//   "12 triangles, 8 vertices, closed, consistently oriented outward, volume 1e-06 m³".
std::string describe(const MeshReport& report);

// Signed volume by the divergence theorem, Σ a·(b×c)/6 (m³); positive for an outward
// closed surface.
double signed_volume(const TriangleMesh& mesh);

// The shell (connected component over shared vertices) of each triangle, numbered from 0 in
// order of first appearance; returns the number of shells.
size_t shell_of_triangles(const TriangleMesh& mesh, std::vector<int32_t>& shell);

// Signed volume of each shell (m³), indexed as shell_of_triangles numbers them.
std::vector<double> shell_volumes(const TriangleMesh& mesh, const std::vector<int32_t>& shell, size_t shells);

}  // namespace latmpm
