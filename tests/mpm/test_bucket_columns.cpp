// A bucket's node columns (bucket_columns.hpp): every node a particle's stencil reaches lies
// in its column's k-range, each range's ends are nodes some stencil reaches, and a column
// no stencil reaches is empty — for the reaches of every shape function. The grid blocks a
// bucket activates from its columns are exactly those holding a column node or a node
// within the halo of one.
#include <catch2/catch.hpp>

#include <random>
#include <set>

#include "mpm/bucket_columns.hpp"

using namespace latmpm::mpm;

namespace {
template <int below, int above>
void check_columns(std::mt19937& rng) {
  Bucket b{};
  b.coord = {-1, 2, 0};
  const int first[3] = {BucketColumns::first_node(b, 0), BucketColumns::first_node(b, 1), BucketColumns::first_node(b, 2)};
  // Cells within the drift limit: 8 coord − 1 … 8 coord + 8 per axis.
  std::uniform_int_distribution<int> offset(-1, 8);
  for (int trial = 0; trial < 20; ++trial) {
    BucketColumns cells;
    std::set<std::array<int, 3>> nodes;  // buffer coordinates of every stencil node
    const int count = 1 + trial * 7;
    for (int n = 0; n < count; ++n) {
      const std::array<int, 3> cell{8 * b.coord[0] + offset(rng), 8 * b.coord[1] + offset(rng), 8 * b.coord[2] + offset(rng)};
      REQUIRE(ParticleBuckets::within_drift(b, cell));
      cells.add_cell(b, cell);
      for (int i = below; i <= above; ++i)
        for (int j = below; j <= above; ++j)
          for (int k = below; k <= above; ++k)
            nodes.insert({cell[0] + i - first[0], cell[1] + j - first[1], cell[2] + k - first[2]});
    }
    const BucketColumns columns = stencil_columns<below, above>(cells);
    constexpr int w = BucketColumns::width;
    for (int i = 0; i < w; ++i)
      for (int j = 0; j < w; ++j) {
        const size_t c = BucketColumns::index(i, j);
        int lo = w, hi = -1;
        for (const auto& n : nodes)
          if (n[0] == i && n[1] == j) lo = std::min(lo, n[2]), hi = std::max(hi, n[2]);
        INFO("reach " << below << ".." << above << ", " << count << " cells, column " << i << ", " << j);
        if (hi < 0) {
          CHECK(columns.lo[c] > columns.hi[c]);
        } else {
          CHECK(int(columns.lo[c]) == lo);
          CHECK(int(columns.hi[c]) == hi);
        }
      }
  }
}
}  // namespace

TEST_CASE("Node columns hold exactly the k-range the cells' stencils reach in each column", "[mpm][buckets]") {
  std::mt19937 rng(7);
  check_columns<0, 1>(rng);   // linear, DDMP's linear part
  check_columns<-1, 2>(rng);  // uGIMP, B-splines, CPDI
  check_columns<-1, 3>(rng);  // cpGIMP
}

namespace {
// The blocks of add_column_blocks against their definition, by brute force: every node of
// every column's range, dilated by `Halo` per axis, mapped to its block.
template <int Halo>
void check_column_blocks(std::mt19937& rng) {
  constexpr int bw = SparseGrid::block_width, w = BucketColumns::width;
  for (const std::array<int, 3> coord : {std::array<int, 3>{0, 0, 0}, {-1, 2, 0}, {3, -4, -2}}) {
    Bucket b{};
    b.coord = coord;
    std::uniform_int_distribution<int> offset(-1, 8);
    for (int trial = 0; trial < 10; ++trial) {
      BucketColumns cells;
      for (int n = 0; n < 1 + trial * 5; ++n)
        cells.add_cell(b, {8 * coord[0] + offset(rng), 8 * coord[1] + offset(rng), 8 * coord[2] + offset(rng)});
      const BucketColumns columns = stencil_columns<-1, 2>(cells);
      std::set<uint64_t> expected;
      int first[3];
      for (int a = 0; a < 3; ++a) first[a] = BucketColumns::first_node(b, a);
      for (int i = 0; i < w; ++i)
        for (int j = 0; j < w; ++j) {
          const size_t c = BucketColumns::index(i, j);
          for (int k = columns.lo[c]; k <= columns.hi[c]; ++k)
            for (int di = -Halo; di <= Halo; ++di)
              for (int dj = -Halo; dj <= Halo; ++dj)
                for (int dk = -Halo; dk <= Halo; ++dk)
                  expected.insert(SparseGrid::block_key(floor_div(first[0] + i + di, bw),
                                                        floor_div(first[1] + j + dj, bw),
                                                        floor_div(first[2] + k + dk, bw)));
        }
      std::vector<uint64_t> keys;
      add_column_blocks<Halo>(b, columns, keys);
      INFO("halo " << Halo << ", bucket " << coord[0] << ", " << coord[1] << ", " << coord[2] << ", trial " << trial);
      CHECK(std::set<uint64_t>(keys.begin(), keys.end()) == expected);
      CHECK(keys.size() == expected.size());  // each block once
    }
  }
}
}  // namespace

TEST_CASE("A bucket activates exactly the grid blocks its node columns and their halo reach", "[mpm][buckets]") {
  std::mt19937 rng(11);
  check_column_blocks<0>(rng);  // the particle shapes
  check_column_blocks<1>(rng);  // DDMP's smoothing on the grid
}
