#include "statics/narrow_band.hpp"

#include <algorithm>

#include "statics/static_shapes.hpp"

namespace latmpm::statics {

namespace {
constexpr int key_bias = 1 << 20;  // grid coordinates within ±2^20 of the origin

uint64_t node_key(const Eigen::Vector3i& c) {  // sorts by k, then j, then i
  return (uint64_t(c[2] + key_bias) << 42) | (uint64_t(c[1] + key_bias) << 21) |
         uint64_t(c[0] + key_bias);
}

struct RawEntry {
  Eigen::Vector3i node;
  Real weight;
  Vec3 gradient;
};

template <class Shape>
void point_entries(const Vec3& x, const Vec3& half, Real inv_h, std::vector<RawEntry>& out) {
  constexpr int N = Shape::nodes_per_axis;
  const auto s = mpm::make_stencil<Shape>(x, half, inv_h);
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j)
      for (int k = 0; k < N; ++k) {
        const Real wx = s.w[i][0], wy = s.w[j][1], wz = s.w[k][2];
        const Vec3 g(s.dw[i][0] * wy * wz, wx * s.dw[j][1] * wz, wx * wy * s.dw[k][2]);
        const Real w = wx * wy * wz;
        if (w == 0 && g.isZero(0)) continue;
        out.push_back({Eigen::Vector3i(s.base[0] + i, s.base[1] + j, s.base[2] + k), w, g});
      }
}
}  // namespace

long NarrowBand::find(const Eigen::Vector3i& c) const {
  const uint64_t key = node_key(c);
  auto it = std::lower_bound(node.begin(), node.end(), key,
                             [](const Eigen::Vector3i& a, uint64_t k) { return node_key(a) < k; });
  return it != node.end() && node_key(*it) == key ? long(it - node.begin()) : -1;
}

NarrowBand build_narrow_band(const std::vector<Vec3>& X, const std::vector<Vec3>& half_size,
                             Real cell_size, mpm::ShapeFunctionKind shape) {
  NarrowBand band;
  band.cell_size = cell_size;
  band.shape = shape;
  const Real inv_h = 1 / cell_size;
  std::vector<RawEntry> raw;
  band.point_offset.assign(1, 0);
  with_static_shape(shape, [&](auto policy) {
    using Shape = decltype(policy);
    band.nodes_per_axis = Shape::nodes_per_axis;
    raw.reserve(X.size() * Shape::nodes_per_axis * Shape::nodes_per_axis * Shape::nodes_per_axis);
    for (size_t p = 0; p < X.size(); ++p) {
      point_entries<Shape>(X[p], half_size[p], inv_h, raw);
      band.point_offset.push_back(uint32_t(raw.size()));
    }
  });

  std::vector<uint64_t> keys(raw.size());
  for (size_t e = 0; e < raw.size(); ++e) keys[e] = node_key(raw[e].node);
  std::vector<uint64_t> unique_keys = keys;
  std::sort(unique_keys.begin(), unique_keys.end());
  unique_keys.erase(std::unique(unique_keys.begin(), unique_keys.end()), unique_keys.end());

  const size_t entries = raw.size(), nodes = unique_keys.size();
  band.node.resize(nodes);
  band.entry_node.resize(entries);
  band.entry_weight.resize(entries);
  band.entry_gradient.resize(entries);
  band.entry_point.resize(entries);
  band.node_entry_offset.assign(nodes + 1, 0);
  for (size_t p = 0; p + 1 < band.point_offset.size(); ++p)
    for (uint32_t e = band.point_offset[p]; e < band.point_offset[p + 1]; ++e) band.entry_point[e] = uint32_t(p);
  for (size_t e = 0; e < entries; ++e) {
    const size_t n = size_t(std::lower_bound(unique_keys.begin(), unique_keys.end(), keys[e]) - unique_keys.begin());
    band.node[n] = raw[e].node;
    band.entry_node[e] = uint32_t(n);
    band.entry_weight[e] = raw[e].weight;
    band.entry_gradient[e] = raw[e].gradient;
    ++band.node_entry_offset[n + 1];
  }
  for (size_t n = 0; n < nodes; ++n) band.node_entry_offset[n + 1] += band.node_entry_offset[n];
  band.node_entry.resize(entries);
  std::vector<uint32_t> fill(band.node_entry_offset.begin(), band.node_entry_offset.end() - 1);
  for (size_t e = 0; e < entries; ++e) band.node_entry[fill[band.entry_node[e]]++] = uint32_t(e);
  return band;
}

}  // namespace latmpm::statics
