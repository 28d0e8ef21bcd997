// Periodic cells and the generic tiler: strut lengths, exact counts from the cell geometry,
// merging of shared nodes and struts.
#include <catch2/catch.hpp>

#include <cmath>

#include "core/units.hpp"
#include "geometry/graph_checks.hpp"
#include "geometry/lattice.hpp"
#include "geometry/plates.hpp"
#include "geometry/strut_graph_builder.hpp"
#include "geometry/unit_cell.hpp"

using namespace latmpm;

TEST_CASE("The builder merges nearby ends and drops repeated struts", "[geometry]") {
  StrutGraphBuilder b(1e-9);
  CHECK(b.strut({0, 0, 0}, {1, 0, 0}, 0.1));
  CHECK_FALSE(b.strut({1 + 4e-10, 0, 0}, {0, 3e-10, 0}, 0.1));  // same strut, reversed
  CHECK(b.strut({1, 0, 0}, {1, 1, 0}, 0.1));
  CHECK(b.node({1, 1, 1e-8}) == 3);  // beyond the tolerance: a new node
  CHECK(b.node_count() == 4);
  CHECK(b.strut_count() == 2);
  CHECK_THROWS_AS(b.strut({0, 0, 0}, {0, 0, 5e-10}, 0.1), std::invalid_argument);
}

TEST_CASE("Tiled periodic cells have struts of one length and the counts of their geometry",
          "[geometry][cells]") {
  const double L = 5e-3;
  const int n = GENERATE(1, 2, 3);
  const std::string cell = GENERATE("bcc", "octet");
  CAPTURE(cell, n);
  const UnitCell unit = cell == "bcc" ? bcc_cell(L) : octet_cell(L);
  const StrutGraph g = tile_unit_cell(unit, n, n, n, 0.5e-3);
  for (const auto& s : g.struts) CHECK(std::abs(strut_length(g, s) - L) < 1e-12);
  const size_t n3 = size_t(n) * n * n, corners = size_t(n + 1) * (n + 1) * (n + 1);
  if (cell == "bcc") {
    // Corners of the cube grid plus one centre per cube; 8 half-diagonals per cube.
    CHECK(g.nodes.size() == corners + n3);
    CHECK(g.struts.size() == 8 * n3);
  } else {
    // FCC points: cube-grid corners plus face centres (3 orientations × n²(n+1) faces);
    // 12 octahedron edges per cube plus 4 struts per face.
    const size_t faces = 3 * size_t(n) * n * (n + 1);
    CHECK(g.nodes.size() == corners + faces);
    CHECK(g.struts.size() == 12 * n3 + 4 * faces);
  }
  CHECK(count_duplicate_nodes(g, 1e-9) == 0);
  CHECK(count_duplicate_struts(g) == 0);
  CHECK(count_bodies(g, 0) == 1);
}

TEST_CASE("A periodic lattice with plates spans whole cells between them", "[geometry][cells]") {
  LatticeSpec spec;
  spec.cell = GENERATE("bcc", "octet");
  spec.strut_length = 5e-3;
  spec.strut_diameter = 1e-3;
  spec.cells = {3, 2, 4};
  spec.plate_thickness = 2e-3;
  spec.plate_margin = 1e-3;
  const StrutGraph g = build_lattice(spec);
  const double a = parse_quantity(g.parameters.at("cell_size")).value;
  CHECK(a == Approx(spec.cell == "bcc" ? 2 * 5e-3 / std::sqrt(3.0) : std::sqrt(2.0) * 5e-3));
  CHECK(parse_quantity(g.parameters.at("layer_height")).value == Approx(a));
  CHECK(parse_quantity(g.parameters.at("lattice_zmax")).value - parse_quantity(g.parameters.at("lattice_zmin")).value ==
        Approx(4 * a));
  // Both cells put round strut ends on the outermost cell corners: the footprint is the
  // cells' extent plus a radius on each side.
  CHECK(parse_quantity(g.parameters.at("footprint_area")).value ==
        Approx((3 * a + spec.strut_diameter) * (2 * a + spec.strut_diameter)));
  const Eigen::AlignedBox3d struts = solid_bounds(g, true);
  REQUIRE(g.plates.size() == 2);
  CHECK(g.plates[0].min.x() == Approx(struts.min().x() - 1e-3));
  CHECK(g.plates[1].max.y() == Approx(struts.max().y() + 1e-3));
  CHECK(g.plates[1].max.z() == Approx(4 * a + 4e-3));
  CHECK(count_bodies(g, 1e-9) == 1);

  spec.plate_thickness = 0;  // without plates the solid, round ends included, starts at z = 0
  const StrutGraph bare = build_lattice(spec);
  CHECK(bare.plates.empty());
  CHECK(std::abs(solid_bounds(bare).min().z()) < 1e-15);
  CHECK(solid_bounds(bare).sizes().z() == Approx(4 * a + spec.strut_diameter));
}
