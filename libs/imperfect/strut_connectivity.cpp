#include "imperfect/strut_connectivity.hpp"

#include <map>
#include <numeric>

namespace latmpm {
namespace {

struct DisjointSets {
  std::vector<int> parent;
  explicit DisjointSets(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void join(int a, int b) { parent[find(a)] = find(b); }
};

}  // namespace

double distance_to_box(const Eigen::Vector3d& x, const Eigen::Vector3d& min, const Eigen::Vector3d& max) {
  return (x.cwiseMax(min).cwiseMin(max) - x).norm();
}

Pieces connected_pieces(const StrutGraph& graph) {
  const int nodes = static_cast<int>(graph.nodes.size());
  DisjointSets sets(graph.nodes.size() + graph.plates.size());
  for (const Strut& s : graph.struts) {
    sets.join(s.a, s.b);
    for (size_t p = 0; p < graph.plates.size(); ++p)
      for (int32_t end : {s.a, s.b})
        if (distance_to_box(graph.nodes[end], graph.plates[p].min, graph.plates[p].max) <= s.radius)
          sets.join(end, nodes + static_cast<int>(p));
  }
  Pieces pieces;
  std::map<int, int> piece_of_root;
  auto piece = [&](int element) {
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
  for (size_t p = 0; p < graph.plates.size(); ++p) pieces.of_plate.push_back(piece(nodes + static_cast<int>(p)));
  return pieces;
}

}  // namespace latmpm
