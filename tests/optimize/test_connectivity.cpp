// The quadrature graph of paper C Sec. 3.4: the narrow band keeps the largest 4/6-connected
// component of the points above the threshold (Eq. 36), and the connectivity correction
// joins solid points that touch through a grid cell but not through the graph (QR
// patterns, Fig. 7), after which the solid set is one component.
#include <catch2/catch.hpp>

#include "optimize/connectivity.hpp"
#include "small_cantilever.hpp"

using namespace latmpm::optimize;

namespace {
// Density from a picture: row 0 is the top (largest y); '#' solid, '.' void.
std::vector<double> from_picture(const DesignGrid& g, const std::vector<std::string>& rows) {
  std::vector<double> rho(g.point_count(), 0);
  const int ny = int(rows.size());
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < int(rows[size_t(j)].size()); ++i)
      if (rows[size_t(j)][size_t(i)] == '#') rho[g.index({i, ny - 1 - j, 0})] = 1;
  return rho;
}
}  // namespace

TEST_CASE("The narrow band keeps the largest connected component and the kept points", "[optimize]") {
  DesignGrid g = test::small_grid(true);
  g.cells = {4, 2, 1};  // 8×4 points
  const auto rho = from_picture(g, {"##....#.",
                                    "##.....#",
                                    "###.....",
                                    "..#...#."});
  CHECK(component_count(g, rho, 0.5) == 4);
  const auto mask = narrow_band_mask(g, rho, 0.5, {g.index({6, 0, 0})});
  size_t active = 0;
  for (char m : mask) active += m;
  CHECK(active == 8 + 1);  // the 8-point block and the kept point
  CHECK(mask[g.index({0, 3, 0})]);
  CHECK(!mask[g.index({6, 3, 0})]);
  CHECK(mask[g.index({6, 0, 0})]);
}

TEST_CASE("The connectivity correction joins points that touch only through a corner", "[optimize]") {
  DesignGrid g = test::small_grid(true);
  g.cells = {4, 2, 1};
  // Two bars meeting at a corner inside one cell: a QR pattern (Fig. 7, left).
  auto rho = from_picture(g, {"....####",
                              "...#....",
                              "..#.....",
                              "##......"});
  CHECK(component_count(g, rho, 0.5) == 4);
  const size_t paths = correct_connectivity(g, rho, 0.5, 2);
  CHECK(paths >= 3);
  CHECK(component_count(g, rho, 0.5) == 1);
  // A straight bar needs no correction.
  auto bar = from_picture(g, {"........", "########", "........", "........"});
  CHECK(correct_connectivity(g, bar, 0.5, 2) == 0);
}
