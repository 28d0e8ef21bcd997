// Hexahedral elements → CPDI1 material points (paper B Sec. 2.2): one point per element at
// its centroid, carrying the element's exact volume and its eight vertices
// (/points/domain_vertices, docs/formats.md). half_size is half the vertices' bounding box,
// so solvers without CPDI can still read the set as GIMP domains.
#pragma once
#include <string>

#include "hexmesh/hex_mesh.hpp"
#include "points/point_set.hpp"

namespace latmpm {

// cell_size: the solver grid the points are meant for (m), recorded in the set.
PointSet hex_mesh_points(const HexMesh& mesh, const std::string& body_name, double cell_size);

}  // namespace latmpm
