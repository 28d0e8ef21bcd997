#include "geometry/graph_checks.hpp"

#include <algorithm>
#include <numeric>
#include <set>
#include <utility>

#include "geometry/strut_graph_builder.hpp"

namespace latmpm {
namespace {

struct DisjointSets {
  std::vector<size_t> parent;
  explicit DisjointSets(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  size_t find(size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void join(size_t a, size_t b) { parent[find(a)] = find(b); }
};

double distance_to_box(const Eigen::Vector3d& p, const Plate& box) {
  return (p.cwiseMax(box.min).cwiseMin(box.max) - p).norm();
}

}  // namespace

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

size_t count_bodies(const StrutGraph& graph, double tolerance) {
  const size_t n = graph.nodes.size(), plates = graph.plates.size();
  DisjointSets sets(n + plates);
  std::vector<bool> used(n + plates, false);
  for (size_t p = 0; p < plates; ++p) used[n + p] = true;
  for (const Strut& s : graph.struts) {
    sets.join(s.a, s.b);
    used[s.a] = used[s.b] = true;
    for (size_t p = 0; p < plates; ++p)
      for (int32_t end : {s.a, s.b})
        if (distance_to_box(graph.nodes[end], graph.plates[p]) <= s.radius + tolerance)
          sets.join(end, n + p);
  }
  std::set<size_t> roots;
  for (size_t i = 0; i < n + plates; ++i)
    if (used[i]) roots.insert(sets.find(i));
  return roots.size();
}

}  // namespace latmpm
