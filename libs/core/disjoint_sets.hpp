// Union–find over the indices 0 … n−1 (path halving), the smaller index of two joined sets as
// their representative: connected components of strut graphs, mesh shells, welded vertices.
#pragma once
#include <algorithm>
#include <numeric>
#include <vector>

namespace latmpm {

template <typename Index = size_t>
struct DisjointSets {
  std::vector<Index> parent;
  explicit DisjointSets(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), Index(0)); }
  Index find(Index x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void join(Index a, Index b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

}  // namespace latmpm
