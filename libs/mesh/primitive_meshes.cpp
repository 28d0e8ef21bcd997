#include "mesh/primitive_meshes.hpp"

#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace latmpm {

TriangleMesh box_mesh(const Eigen::Vector3d& min, const Eigen::Vector3d& max) {
  TriangleMesh m;
  for (int i = 0; i < 8; ++i)  // vertex i has bit 0 → x, bit 1 → y, bit 2 → z at max
    m.vertices.emplace_back(i & 1 ? max.x() : min.x(), i & 2 ? max.y() : min.y(),
                            i & 4 ? max.z() : min.z());
  // Two triangles per face, counter-clockwise seen from outside.
  m.triangles = {{0, 2, 1}, {1, 2, 3},   // z = min
                 {4, 5, 6}, {5, 7, 6},   // z = max
                 {0, 1, 4}, {1, 5, 4},   // y = min
                 {2, 6, 3}, {3, 6, 7},   // y = max
                 {0, 4, 2}, {2, 4, 6},   // x = min
                 {1, 3, 5}, {3, 7, 5}};  // x = max
  return m;
}

TriangleMesh sphere_mesh(const Eigen::Vector3d& centre, double radius, int subdivisions) {
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Eigen::Vector3d> unit = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0},
                                       {0, -1, g}, {0, 1, g}, {0, -1, -g}, {0, 1, -g},
                                       {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
  for (auto& v : unit) v.normalize();
  std::vector<std::array<int32_t, 3>> tris = {
      {0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
      {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<int32_t, int32_t>, int32_t> midpoint;
    auto middle = [&](int32_t a, int32_t b) {
      const auto key = std::minmax(a, b);
      auto it = midpoint.find(key);
      if (it != midpoint.end()) return it->second;
      unit.push_back((unit[a] + unit[b]).normalized());
      const auto index = static_cast<int32_t>(unit.size() - 1);
      midpoint.emplace(key, index);
      return index;
    };
    std::vector<std::array<int32_t, 3>> finer;
    finer.reserve(4 * tris.size());
    for (const auto& t : tris) {
      const int32_t ab = middle(t[0], t[1]), bc = middle(t[1], t[2]), ca = middle(t[2], t[0]);
      finer.push_back({t[0], ab, ca});
      finer.push_back({t[1], bc, ab});
      finer.push_back({t[2], ca, bc});
      finer.push_back({ab, bc, ca});
    }
    tris.swap(finer);
  }
  TriangleMesh m;
  for (const auto& v : unit) m.vertices.push_back(centre + radius * v);
  m.triangles = std::move(tris);
  return m;
}

TriangleMesh cylinder_mesh(const Eigen::Vector3d& base_centre, double radius, double height,
                           int segments) {
  TriangleMesh m;
  const auto n = static_cast<int32_t>(segments);
  for (int level = 0; level < 2; ++level)
    for (int32_t i = 0; i < n; ++i) {
      const double a = 2.0 * M_PI * i / n;
      m.vertices.push_back(base_centre + Eigen::Vector3d(radius * std::cos(a), radius * std::sin(a),
                                                         level * height));
    }
  const int32_t bottom = 2 * n, top = 2 * n + 1;
  m.vertices.push_back(base_centre);
  m.vertices.push_back(base_centre + Eigen::Vector3d(0, 0, height));
  for (int32_t i = 0; i < n; ++i) {
    const int32_t j = (i + 1) % n;
    m.triangles.push_back({i, j, n + j});  // side, outward
    m.triangles.push_back({i, n + j, n + i});
    m.triangles.push_back({bottom, j, i});  // bottom cap, facing −z
    m.triangles.push_back({top, n + i, n + j});  // top cap, facing +z
  }
  return m;
}

}  // namespace latmpm
