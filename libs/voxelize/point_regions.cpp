#include "voxelize/point_regions.hpp"

#include <algorithm>
#include <climits>
#include <cmath>

namespace latmpm {
namespace {

// The z index m of a point at z = (m + ½)Δ.
int64_t layer_of(const PointSet& p, size_t i) {
  const double spacing = p.cell_size / p.ppc;
  return static_cast<int64_t>(std::llround(p.position[i].z() / spacing - 0.5));
}

}  // namespace

void assign_strut_graph_bodies(PointSet& points, const StrutGraph& graph) {
  const size_t plates = graph.plates.size();
  std::vector<size_t> count(plates + 1, 0);
  std::vector<int32_t> raw(points.size(), 0);  // 0 struts, 1 + k plate k
  for (size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d& x = points.position[i];
    for (size_t k = 0; k < plates; ++k) {
      const Plate& plate = graph.plates[k];
      if ((x.array() >= plate.min.array()).all() && (x.array() <= plate.max.array()).all()) {
        raw[i] = static_cast<int32_t>(k + 1);
        break;
      }
    }
    ++count[static_cast<size_t>(raw[i])];
  }
  // Only bodies that received points get a name and an index, in order struts, plates.
  std::vector<int32_t> index(plates + 1, -1);
  points.body_names.clear();
  for (size_t b = 0; b <= plates; ++b) {
    if (count[b] == 0) continue;
    index[b] = static_cast<int32_t>(points.body_names.size());
    points.body_names.push_back(b == 0 ? graph.strut_body : graph.plates[b - 1].name);
  }
  points.body.resize(points.size());
  for (size_t i = 0; i < points.size(); ++i) points.body[i] = index[static_cast<size_t>(raw[i])];
}

void tag_regions(PointSet& points, const std::vector<std::string>& plate_names) {
  const size_t n = points.size();
  const size_t bodies = points.body_names.size();
  if (n == 0 || bodies == 0) return;
  std::vector<int64_t> lowest(bodies, INT64_MAX), highest(bodies, INT64_MIN);
  for (size_t i = 0; i < n; ++i) {
    const auto b = static_cast<size_t>(points.body[i]);
    const int64_t m = layer_of(points, i);
    lowest[b] = std::min(lowest[b], m);
    highest[b] = std::max(highest[b], m);
  }
  const auto lowest_body = static_cast<int32_t>(std::min_element(lowest.begin(), lowest.end()) - lowest.begin());
  const auto top_body = static_cast<int32_t>(std::max_element(highest.begin(), highest.end()) - highest.begin());
  const int record_named = points.body_index("bottom_plate");
  const int32_t record_body = record_named >= 0 ? record_named : lowest_body;
  const int64_t bottom = lowest[static_cast<size_t>(lowest_body)];

  auto& record = points.tags["record"];
  auto& bottom_layer = points.tags["bottom_layer"];
  auto& top_layer = points.tags["top_layer"];
  record.assign(n, 0);
  bottom_layer.assign(n, 0);
  top_layer.assign(n, 0);
  for (size_t i = 0; i < n; ++i) {
    const int32_t b = points.body[i];
    const int64_t m = layer_of(points, i);
    record[i] = b == record_body && m == lowest[static_cast<size_t>(b)];
    bottom_layer[i] = m == bottom;
    top_layer[i] = b == top_body && m == highest[static_cast<size_t>(b)];
  }
  for (const std::string& plate : plate_names) {
    const int b = points.body_index(plate);
    if (b < 0) continue;
    auto& mask = points.tags[plate];
    mask.assign(n, 0);
    for (size_t i = 0; i < n; ++i) mask[i] = points.body[i] == b;
  }
}

}  // namespace latmpm
