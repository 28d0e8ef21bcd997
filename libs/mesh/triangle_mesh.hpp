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

// Adds `from`'s triangles (and vertices) to `to`, as separate shells.
inline void append(TriangleMesh& to, const TriangleMesh& from) {
  const auto offset = static_cast<int32_t>(to.vertices.size());
  to.vertices.insert(to.vertices.end(), from.vertices.begin(), from.vertices.end());
  for (auto t : from.triangles) to.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
}

}  // namespace latmpm
