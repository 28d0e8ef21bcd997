// A triangle surface: what STL files hold, what volumeToMesh produces, what CGAL checks.
// Lengths in metres. Triangles index into vertices, counter-clockwise seen from outside.
#pragma once
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

namespace latmpm {

struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int32_t, 3>> triangles;
};

}  // namespace latmpm
