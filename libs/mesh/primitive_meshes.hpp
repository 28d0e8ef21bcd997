// Closed, outward-oriented triangle meshes of simple solids whose volumes are known exactly:
// for tests, benchmarks and sample STL files. Lengths in metres.
#pragma once
#include <Eigen/Core>

#include "mesh/triangle_mesh.hpp"

namespace latmpm {

// Axis-aligned box, 12 triangles. Volume = Π (max − min).
TriangleMesh box_mesh(const Eigen::Vector3d& min, const Eigen::Vector3d& max);

// Icosphere: an icosahedron subdivided `subdivisions` times (20·4^s triangles), vertices on
// the sphere. Its volume is below (4/3)πr³ and exactly signed_volume() of the mesh.
TriangleMesh sphere_mesh(const Eigen::Vector3d& centre, double radius, int subdivisions);

// Cylinder along z from `base_centre` up by `height`, the circle as a regular polygon of
// `segments` sides (vertices on the circle). Volume = (segments/2)·r²·sin(2π/segments)·height.
TriangleMesh cylinder_mesh(const Eigen::Vector3d& base_centre, double radius, double height,
                           int segments);

}  // namespace latmpm
