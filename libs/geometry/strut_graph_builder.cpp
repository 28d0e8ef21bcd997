#include "geometry/strut_graph_builder.hpp"

#include <cmath>
#include <stdexcept>

namespace latmpm {

StrutGraphBuilder::StrutGraphBuilder(double merge_tolerance) : tolerance_(merge_tolerance) {
  if (!(merge_tolerance > 0)) throw std::invalid_argument("merge tolerance must be positive");
}

int64_t StrutGraphBuilder::cell_key(int64_t i, int64_t j, int64_t k) const {
  // 21 bits per axis; indices beyond wrap around, which only makes unrelated nodes share a
  // hash cell: node() compares actual distances, so merging stays exact.
  const int64_t mask = (int64_t(1) << 21) - 1;
  return ((i & mask) << 42) | ((j & mask) << 21) | (k & mask);
}

int32_t StrutGraphBuilder::node(const Eigen::Vector3d& p) {
  // Hash cells as large as the tolerance: a node within tolerance of p lies in one of the
  // 27 cells around p's cell.
  const int64_t ci = std::llround(std::floor(p.x() / tolerance_));
  const int64_t cj = std::llround(std::floor(p.y() / tolerance_));
  const int64_t ck = std::llround(std::floor(p.z() / tolerance_));
  for (int64_t di = -1; di <= 1; ++di)
    for (int64_t dj = -1; dj <= 1; ++dj)
      for (int64_t dk = -1; dk <= 1; ++dk) {
        auto range = cells_.equal_range(cell_key(ci + di, cj + dj, ck + dk));
        for (auto it = range.first; it != range.second; ++it)
          if ((nodes_[it->second] - p).norm() <= tolerance_) return it->second;
      }
  const auto index = static_cast<int32_t>(nodes_.size());
  nodes_.push_back(p);
  cells_.emplace(cell_key(ci, cj, ck), index);
  return index;
}

bool StrutGraphBuilder::strut(const Eigen::Vector3d& p, const Eigen::Vector3d& q, double radius) {
  const int32_t a = node(p), b = node(q);
  if (a == b) throw std::invalid_argument("a strut of zero length");
  if (!strut_keys_.insert({std::min(a, b), std::max(a, b)}).second) return false;
  struts_.push_back({a, b, radius});
  return true;
}

void StrutGraphBuilder::move_into(StrutGraph& graph) {
  graph.nodes = std::move(nodes_);
  graph.struts = std::move(struts_);
  nodes_.clear();
  struts_.clear();
  cells_.clear();
  strut_keys_.clear();
}

}  // namespace latmpm
