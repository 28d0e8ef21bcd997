// Assembles a strut graph from struts given by their end points: coincident ends become one
// node (tolerance-based spatial hashing), and a strut added twice (either direction) is kept
// once. Every cell type and tiling rule builds its graph through this, so no generator has to
// track node indices or shared struts itself.
#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <unordered_map>
#include <set>
#include <utility>
#include <vector>

#include "geometry/strut_graph.hpp"

namespace latmpm {

class StrutGraphBuilder {
 public:
  // Points closer than `merge_tolerance` (m) are the same node.
  explicit StrutGraphBuilder(double merge_tolerance);

  // Index of the node at p, creating it when no node lies within the tolerance.
  int32_t node(const Eigen::Vector3d& p);
  // Adds the strut p–q unless it exists already; false when it was a duplicate.
  // Throws std::invalid_argument for a zero-length strut (a generator bug, not bad input).
  bool strut(const Eigen::Vector3d& p, const Eigen::Vector3d& q, double radius);

  size_t node_count() const { return nodes_.size(); }
  size_t strut_count() const { return struts_.size(); }
  // Moves nodes and struts into `graph` (replacing its nodes and struts).
  void move_into(StrutGraph& graph);

 private:
  int64_t cell_key(int64_t i, int64_t j, int64_t k) const;

  double tolerance_;
  std::vector<Eigen::Vector3d> nodes_;
  std::vector<Strut> struts_;
  std::unordered_multimap<int64_t, int32_t> cells_;  // hash cell -> nodes in it
  std::set<std::pair<int32_t, int32_t>> strut_keys_;
};

}  // namespace latmpm
