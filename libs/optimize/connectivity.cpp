#include "optimize/connectivity.hpp"

#include <algorithm>
#include <deque>
#include <map>

namespace latmpm::optimize {
namespace {

// The 4 (2D) or 6 (3D) lattice neighbours of point q inside the grid.
template <class F>
void for_lattice_neighbours(const DesignGrid& grid, size_t q, F&& f) {
  const Index3 l = grid.lattice_coord(q);
  for (int a = 0; a < grid.dimension(); ++a)
    for (int step : {-1, 1}) {
      Index3 m = l;
      m[a] += step;
      if (grid.inside(m)) f(grid.index(m));
    }
}

// Component label per point (−1 for points at or below the threshold); returns the count.
int label_components(const DesignGrid& grid, const std::vector<Real>& density, Real threshold,
                     std::vector<int>& label, std::vector<size_t>& size) {
  const size_t n = grid.point_count();
  label.assign(n, -1);
  size.clear();
  std::deque<size_t> queue;
  for (size_t start = 0; start < n; ++start) {
    if (label[start] >= 0 || !(density[start] > threshold)) continue;
    const int id = int(size.size());
    size.push_back(0);
    label[start] = id;
    queue.push_back(start);
    while (!queue.empty()) {
      const size_t q = queue.front();
      queue.pop_front();
      ++size[size_t(id)];
      for_lattice_neighbours(grid, q, [&](size_t m) {
        if (label[m] < 0 && density[m] > threshold) {
          label[m] = id;
          queue.push_back(m);
        }
      });
    }
  }
  return int(size.size());
}

}  // namespace

std::vector<char> narrow_band_mask(const DesignGrid& grid, const std::vector<Real>& density, Real threshold,
                                   const std::vector<size_t>& keep, const std::vector<size_t>& anchors,
                                   bool* joined) {
  if (joined) *joined = false;
  std::vector<int> label;
  std::vector<size_t> size;
  label_components(grid, density, threshold, label, size);
  std::vector<char> mask(grid.point_count(), 0);
  if (!size.empty()) {
    // The largest component holding an anchor and a kept point, else one holding an anchor.
    std::vector<char> anchored(size.size(), 0), loaded(size.size(), 0);
    for (size_t q : anchors)
      if (label[q] >= 0) anchored[size_t(label[q])] = 1;
    for (size_t q : keep)
      if (label[q] >= 0) loaded[size_t(label[q])] = 1;
    int largest = -1;
    for (int pass = 0; pass < 2 && largest < 0; ++pass) {
      for (size_t c = 0; c < size.size(); ++c)
        if (anchored[c] && (pass == 1 || loaded[c]) && (largest < 0 || size[c] > size[size_t(largest)])) largest = int(c);
      if (pass == 0 && largest >= 0 && joined) *joined = true;
    }
    if (largest < 0) largest = int(std::max_element(size.begin(), size.end()) - size.begin());
    for (size_t q = 0; q < mask.size(); ++q) mask[q] = label[q] == largest;
  }
  for (size_t q : keep) mask[q] = 1;
  return mask;
}

size_t component_count(const DesignGrid& grid, const std::vector<Real>& density, Real threshold) {
  std::vector<int> label;
  std::vector<size_t> size;
  return size_t(label_components(grid, density, threshold, label, size));
}

size_t correct_connectivity(const DesignGrid& grid, std::vector<Real>& density, Real threshold, int slack,
                            Real solid) {
  // Two points in one cell or in cells sharing a node lie within 2n − 1 lattice steps per
  // axis (n points per cell): search the graph that far, plus the slack.
  const int reach = 2 * grid.per_cell - 1;
  const int dim = grid.dimension();
  const int max_depth = dim * reach + slack + 1;
  size_t paths = 0;
  for (size_t a = 0; a < grid.point_count(); ++a) {
    if (!(density[a] > threshold)) continue;
    const Index3 la = grid.lattice_coord(a), ca = grid.cell_of(a);
    for (bool corrected = true; corrected;) {  // until no pair of a needs a path
      corrected = false;
      // Bounded BFS from a over solid points.
      std::map<size_t, int> distance{{a, 0}};
      std::deque<size_t> queue{a};
      while (!queue.empty()) {
        const size_t q = queue.front();
        queue.pop_front();
        const int d = distance[q];
        if (d >= max_depth) continue;
        for_lattice_neighbours(grid, q, [&](size_t m) {
          if (density[m] > threshold && !distance.count(m)) {
            distance[m] = d + 1;
            queue.push_back(m);
          }
        });
      }
      // Pairs (a, b), b > a, whose cells are one cell or share a node.
      Index3 lo = la.array() - reach, hi = la.array() + reach;
      if (grid.planar) lo[2] = hi[2] = 0;
      for (int k = lo[2]; k <= hi[2] && !corrected; ++k)
        for (int j = lo[1]; j <= hi[1] && !corrected; ++j)
          for (int i = lo[0]; i <= hi[0] && !corrected; ++i) {
            const Index3 lb(i, j, k);
            if (!grid.inside(lb)) continue;
            const size_t b = grid.index(lb);
            if (b <= a || !(density[b] > threshold)) continue;
            if (((grid.cell_of(b) - ca).array().abs() > 1).any()) continue;
            const int manhattan = (lb - la).array().abs().sum();
            const auto found = distance.find(b);
            const int graph = found == distance.end() ? max_depth + 1 : found->second;
            if (graph - manhattan <= slack) continue;
            // Axis by axis from a to b: one shortest Manhattan path, made solid.
            Index3 l = la;
            for (int axis = 0; axis < 3; ++axis)
              while (l[axis] != lb[axis]) {
                l[axis] += lb[axis] > l[axis] ? 1 : -1;
                density[grid.index(l)] = std::max(density[grid.index(l)], solid);
              }
            ++paths;
            corrected = true;
          }
    }
  }
  return paths;
}

}  // namespace latmpm::optimize
