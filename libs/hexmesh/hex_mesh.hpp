// Hexahedral meshes for CPDI1 particle domains (paper B Sec. 2.2 and Fig. 7: "each finite
// element from these meshes is used as a particle domain"). Meshes are made and read through
// gmsh's API: a structured O-grid cylinder (a transfinite core square and four transfinite
// ring patches, recombined into quadrilaterals and extruded in recombined layers), a
// structured box, and any .msh file of 8-node hexahedra. Vertex order is gmsh's
// (points/hexahedron.hpp); every element is returned with a positive Jacobian.
#pragma once
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

namespace latmpm {

struct HexMesh {
  std::vector<Eigen::Vector3d> nodes;              // m
  std::vector<std::array<size_t, 8>> elements;     // indices into nodes, gmsh vertex order
};

// O-grid cylinder about the z axis from z = 0 to z = height: the core square has
// core_divisions elements per side, the ring ring_divisions across, the height
// axial_divisions layers. The circumference gets 4·core_divisions elements whose outer
// vertices lie on the circle; the meshed volume is that of the inscribed prism.
struct CylinderMeshSpec {
  double diameter = 0;  // m
  double height = 0;    // m
  int core_divisions = 2;
  int ring_divisions = 1;
  int axial_divisions = 4;
  double core_fraction = 0.4;  // half-width of the core square over the radius
  int elements() const { return axial_divisions * (core_divisions * core_divisions + 4 * core_divisions * ring_divisions); }
};

// The refinement levels of paper B's meshes B1–B6 (Table 2's counts are not in the text;
// docs/paper-b.md): level k has core 2k, ring k, axial 4k, i.e. 48 k³ elements of about
// d/(4k) on a side.
CylinderMeshSpec paper_b_cylinder(int level, double diameter, double height);

// Sizes in m. Throws InputError("hex mesh", field, problem) for non-positive sizes or divisions.
HexMesh cylinder_hex_mesh(const CylinderMeshSpec& spec, const std::string& msh_path = "");
HexMesh box_hex_mesh(const Eigen::Vector3d& lower, const Eigen::Vector3d& upper, const Eigen::Vector3i& divisions,
                     const std::string& msh_path = "");

// Reads the 8-node hexahedra of a gmsh .msh file (coordinates times metres_per_unit).
// Throws InputError naming the file when it holds no 8-node hexahedra, holds other volume
// elements (tetrahedra, prisms, pyramids, higher-order hexahedra), or an inverted element.
HexMesh read_hex_mesh(const std::string& path, double metres_per_unit);

// Exact volume of the whole mesh (sum of the trilinear elements' volumes), m³.
double hex_mesh_volume(const HexMesh& mesh);

}  // namespace latmpm
