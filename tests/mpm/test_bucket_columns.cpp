// A bucket's node columns (bucket_columns.hpp): every node a particle's stencil reaches lies
// in its column's k-range, each range's ends are nodes some stencil reaches, and a column
// no stencil reaches is empty — for the reaches of every shape function.
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
