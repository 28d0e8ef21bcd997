// Rasterising the union of struts and plates leaf by leaf (8³-voxel blocks), in parallel.
//
// 1. For every primitive, list the leaves its bounding box (grown by the band half-width w)
//    touches: pairs (leaf, primitive), sorted by leaf.
// 2. For every leaf, independently: with the distance d_c of each candidate at the leaf
//    centre and the leaf's half-diagonal r (distances are 1-Lipschitz), a candidate with
//    d_c + r ≤ −w puts the whole leaf deep inside (skip: flood fill makes it interior), and a
//    candidate with d_c − r ≥ w cannot reach the band here (drop it). Otherwise every voxel
//    gets min over the remaining candidates, clamped to [−w, w]; |d| < w voxels are active.
// 3. Add the leaves that have an active voxel to the tree, then sign-flood-fill the rest.
// Each leaf is written once by one thread with the full minimum: no merging, no race, and
// no voxel in one primitive's band keeps a value that another primitive's interior overrides.
#include "levelset/strut_level_set.hpp"

#include <openvdb/tools/Prune.h>
#include <openvdb/tools/SignedFloodFill.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include "levelset/level_set_units.hpp"
#include "levelset/solid_primitive.hpp"

namespace latmpm {
namespace {

using LeafType = openvdb::FloatTree::LeafNodeType;
constexpr int leaf_dim = LeafType::DIM;  // 8

// The primitives in grid units (level_set_units.hpp).
std::vector<SolidPrimitive> primitives_of(const StrutGraph& graph) {
  std::vector<SolidPrimitive> out;
  const auto kind = graph.strut_ends == StrutEnds::flat ? SolidPrimitive::Kind::cylinder
                                                        : SolidPrimitive::Kind::capsule;
  const double k = grid_units_per_metre;
  for (const Strut& s : graph.struts)
    out.push_back({kind, k * graph.nodes[s.a], k * graph.nodes[s.b], k * s.radius});
  for (const Plate& p : graph.plates) out.push_back({SolidPrimitive::Kind::box, k * p.min, k * p.max, 0});
  return out;
}

// Leaf origins are multiples of 8 in index space; a leaf index is origin / 8, packed in 21
// bits per axis (±2^20 leaves, i.e. ±8.4 million voxels per axis).
constexpr int64_t key_bias = int64_t(1) << 20;
int64_t pack(int64_t i, int64_t j, int64_t k) {
  return ((i + key_bias) << 42) | ((j + key_bias) << 21) | (k + key_bias);
}
openvdb::Coord unpack_origin(int64_t key) {
  const int64_t mask = (int64_t(1) << 21) - 1;
  return openvdb::Coord(int((((key >> 42) & mask) - key_bias) * leaf_dim),
                        int((((key >> 21) & mask) - key_bias) * leaf_dim),
                        int(((key & mask) - key_bias) * leaf_dim));
}
int64_t floor_div(int64_t a, int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

}  // namespace

openvdb::FloatGrid::Ptr strut_graph_level_set(const StrutGraph& graph, double voxel_size_m,
                                              double half_width_voxels) {
  return strut_graph_level_set(graph, voxel_size_m, half_width_voxels, {});
}

openvdb::FloatGrid::Ptr strut_graph_level_set(const StrutGraph& graph, double voxel_size_m,
                                              double half_width_voxels,
                                              const std::function<void(double)>& progress) {
  if (!(voxel_size_m >= smallest_voxel_m) || !std::isfinite(voxel_size_m))
    throw std::invalid_argument("strut_graph_level_set: voxel size must be at least 0.1 um");
  if (!(half_width_voxels >= 1))
    throw std::invalid_argument("strut_graph_level_set: band half-width must be at least 1 voxel");
  openvdb::initialize();
  // Lengths and distances below are in grid units (mm), not metres.
  const double h = voxel_size_m * grid_units_per_metre, w = half_width_voxels * h;
  const float background = float(w);
  auto grid = openvdb::FloatGrid::create(background);
  grid->setTransform(level_set_transform(voxel_size_m));
  grid->setGridClass(openvdb::GRID_LEVEL_SET);
  grid->setName("solid");
  const std::vector<SolidPrimitive> primitives = primitives_of(graph);
  if (primitives.empty()) return grid;

  // 1. (leaf, primitive) pairs.
  std::vector<std::pair<int64_t, int32_t>> pairs;
  for (size_t p = 0; p < primitives.size(); ++p) {
    const Eigen::Vector3d lo = primitives[p].lower().array() - w, hi = primitives[p].upper().array() + w;
    int64_t first[3], last[3];
    for (int axis = 0; axis < 3; ++axis) {
      first[axis] = floor_div(int64_t(std::floor(lo[axis] / h)), leaf_dim);
      last[axis] = floor_div(int64_t(std::ceil(hi[axis] / h)), leaf_dim);
      if (first[axis] <= -key_bias || last[axis] >= key_bias)
        throw std::invalid_argument("strut_graph_level_set: solid too large for this voxel size");
    }
    for (int64_t i = first[0]; i <= last[0]; ++i)
      for (int64_t j = first[1]; j <= last[1]; ++j)
        for (int64_t k = first[2]; k <= last[2]; ++k) pairs.emplace_back(pack(i, j, k), int32_t(p));
  }
  std::sort(pairs.begin(), pairs.end());
  std::vector<size_t> group_start;
  for (size_t i = 0; i < pairs.size(); ++i)
    if (i == 0 || pairs[i].first != pairs[i - 1].first) group_start.push_back(i);
  group_start.push_back(pairs.size());
  const size_t groups = group_start.size() - 1;

  // 2. Leaves, each computed by one task.
  std::vector<LeafType*> leaves(groups, nullptr);
  const double half_diagonal = std::sqrt(3.0) * 0.5 * (leaf_dim - 1) * h;
  std::atomic<size_t> done{0};
  auto compute = [&](const tbb::blocked_range<size_t>& range) {
    std::vector<const SolidPrimitive*> near;
    for (size_t g = range.begin(); g != range.end(); ++g) {
      const openvdb::Coord origin = unpack_origin(pairs[group_start[g]].first);
      const Eigen::Vector3d centre =
          h * (Eigen::Vector3d(origin.x(), origin.y(), origin.z()).array() + 0.5 * (leaf_dim - 1));
      near.clear();
      bool deep_inside = false;
      for (size_t i = group_start[g]; i < group_start[g + 1] && !deep_inside; ++i) {
        const SolidPrimitive& prim = primitives[pairs[i].second];
        const double d = prim.distance(centre);
        if (d + half_diagonal <= -w) deep_inside = true;
        else if (d - half_diagonal < w) near.push_back(&prim);
      }
      if (deep_inside || near.empty()) continue;
      auto leaf = std::make_unique<LeafType>(origin, background, false);
      bool any_active = false;
      for (int i = 0; i < leaf_dim; ++i)
        for (int j = 0; j < leaf_dim; ++j)
          for (int k = 0; k < leaf_dim; ++k) {
            const openvdb::Coord ijk = origin.offsetBy(i, j, k);
            const Eigen::Vector3d p = h * Eigen::Vector3d(ijk.x(), ijk.y(), ijk.z());
            double d = w;
            for (const SolidPrimitive* prim : near) d = std::min(d, prim->distance(p));
            const auto offset = LeafType::coordToOffset(ijk);
            if (std::abs(d) < w) {
              leaf->setValueOn(offset, float(d));
              any_active = true;
            } else {
              leaf->setValueOff(offset, d < 0 ? -background : background);
            }
          }
      if (any_active) leaves[g] = leaf.release();
    }
    done += range.size();
  };
  const size_t chunk = std::max<size_t>(1, groups / 50);
  for (size_t begin = 0; begin < groups; begin += chunk) {
    tbb::parallel_for(tbb::blocked_range<size_t>(begin, std::min(groups, begin + chunk), 16), compute);
    if (progress) progress(double(done) / double(groups));
  }

  // 3. Assemble, then resolve the sign of everything outside the band.
  openvdb::FloatTree& tree = grid->tree();
  for (LeafType* leaf : leaves)
    if (leaf) tree.addLeaf(leaf);
  openvdb::tools::signedFloodFill(tree);
  openvdb::tools::pruneLevelSet(tree);
  return grid;
}

}  // namespace latmpm
