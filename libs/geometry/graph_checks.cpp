#include "geometry/graph_checks.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <utility>

#include "core/disjoint_sets.hpp"
#include "geometry/strut_graph_builder.hpp"

namespace latmpm {

double distance_to_box(const Eigen::Vector3d& x, const Eigen::Vector3d& min, const Eigen::Vector3d& max) {
  return (x.cwiseMax(min).cwiseMin(max) - x).norm();
}

double strut_length(const StrutGraph& graph, const Strut& strut) {
  return (graph.nodes[strut.b] - graph.nodes[strut.a]).norm();
}

size_t count_duplicate_nodes(const StrutGraph& graph, double tolerance) {
  StrutGraphBuilder merger(tolerance);
  for (const auto& n : graph.nodes) merger.node(n);
  return graph.nodes.size() - merger.node_count();
}

size_t count_duplicate_struts(const StrutGraph& graph) {
  std::set<std::pair<int32_t, int32_t>> seen;
  size_t duplicates = 0;
  for (const Strut& s : graph.struts)
    if (!seen.insert({std::min(s.a, s.b), std::max(s.a, s.b)}).second) ++duplicates;
  return duplicates;
}

Pieces connected_pieces(const StrutGraph& graph, double tolerance) {
  const size_t nodes = graph.nodes.size();
  DisjointSets<> sets(nodes + graph.plates.size());
  for (const Strut& s : graph.struts) {
    sets.join(s.a, s.b);
    for (size_t p = 0; p < graph.plates.size(); ++p)
      for (int32_t end : {s.a, s.b})
        if (distance_to_box(graph.nodes[end], graph.plates[p].min, graph.plates[p].max) <=
            s.radius + tolerance)
          sets.join(end, nodes + p);
  }
  Pieces pieces;
  std::map<size_t, int> piece_of_root;
  auto piece = [&](size_t element) {
    auto it = piece_of_root.emplace(sets.find(element), pieces.count);
    if (it.second) {
      ++pieces.count;
      pieces.struts_in.push_back(0);
    }
    return it.first->second;
  };
  for (const Strut& s : graph.struts) {
    pieces.of_strut.push_back(piece(s.a));
    ++pieces.struts_in[pieces.of_strut.back()];
  }
  for (size_t p = 0; p < graph.plates.size(); ++p) pieces.of_plate.push_back(piece(nodes + p));
  return pieces;
}

size_t count_bodies(const StrutGraph& graph, double tolerance) {
  return static_cast<size_t>(connected_pieces(graph, tolerance).count);
}

}  // namespace latmpm
