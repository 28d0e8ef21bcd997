// The tetrahedral lattice against its definition (REFERENCE.md "Tetrahedral lattice"):
// heights, strut lengths, connectivity, counts, and the layer-to-layer joints.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "core/units.hpp"
#include "geometry/graph_checks.hpp"
#include "geometry/lattice.hpp"
#include "geometry/plates.hpp"

using namespace latmpm;

namespace {

double parameter(const StrutGraph& g, const std::string& key) {
  REQUIRE(g.parameters.count(key));
  return parse_quantity(g.parameters.at(key)).value;
}

std::vector<int> node_degrees(const StrutGraph& g) {
  std::vector<int> degree(g.nodes.size(), 0);
  for (const auto& s : g.struts) ++degree[s.a], ++degree[s.b];
  return degree;
}

}  // namespace

TEST_CASE("Every preset has the paper's heights, strut lengths and one connected body",
          "[geometry][lattice]") {
  const std::string preset = GENERATE(from_range(preset_names()));
  CAPTURE(preset);
  const LatticeSpec spec = preset_lattice(preset);
  const StrutGraph g = build_lattice(spec);
  const double L = 8e-3, T = 3e-3, phi = std::stoi(preset.substr(3)) * M_PI / 180;
  const double h = L * std::sin(phi) + 2 * L / 3;

  CHECK(spec.strut_diameter == (preset[1] == '1' ? 1.6e-3 : 2.4e-3));
  CHECK(std::abs(parameter(g, "layer_height") - h) < 1e-9);
  CHECK(std::abs(parameter(g, "lattice_zmin") - T) < 1e-9);
  CHECK(std::abs(parameter(g, "lattice_zmax") - (T + 5 * h)) < 1e-9);
  CHECK(std::abs(parameter(g, "angle") - phi) < 1e-9);
  const Eigen::AlignedBox3d box = solid_bounds(g);
  CHECK(std::abs(box.min().z()) < 1e-9);
  CHECK(std::abs(box.max().z() - (5 * h + 2 * T)) < 1e-9);

  // Node heights: feet/vertical tops at T + i·h, tripod nodes L sin φ above the feet.
  for (const auto& n : g.nodes) {
    const double above_feet = std::fmod(n.z() - T + 1e-12, h) - 1e-12;
    const bool on_feet_level = std::abs(above_feet) < 1e-9 || std::abs(above_feet - h) < 1e-9;
    const bool on_node_level = std::abs(above_feet - L * std::sin(phi)) < 1e-9;
    CHECK((on_feet_level || on_node_level));
  }
  size_t inclined = 0, vertical = 0;
  for (const auto& s : g.struts) {
    const double length = strut_length(g, s);
    if (std::abs(length - L) < 1e-9) ++inclined;
    else if (std::abs(length - 2 * L / 3) < 1e-9) ++vertical;
    CHECK(s.radius == spec.strut_diameter / 2);
  }
  // 25 tripods per layer, five layers: three inclined struts and one vertical each.
  CHECK(inclined == 3 * 125);
  CHECK(vertical == 125);
  CHECK(g.struts.size() == inclined + vertical);
  CHECK(g.nodes.size() == 325);  // the REFERENCE.md prototype's count for 5x5x5
  CHECK(count_duplicate_nodes(g, 1e-6) == 0);
  CHECK(count_duplicate_struts(g) == 0);
  CHECK(count_bodies(g, 1e-9) == 1);
  REQUIRE(g.plates.size() == 2);
  CHECK(g.plates[0].max.z() == Approx(T));
  CHECK(g.plates[1].min.z() == Approx(T + 5 * h));
}

TEST_CASE("Each layer holds nx by ny tripods whose vertical struts carry the next layer",
          "[geometry][lattice]") {
  LatticeSpec spec = preset_lattice("T2P30");
  spec.stacking = GENERATE(Stacking::abc, Stacking::acb);
  spec.footprint = GENERATE(Footprint::brick, Footprint::rhombic);
  spec.cells = GENERATE(std::array<int, 3>{5, 5, 5}, std::array<int, 3>{4, 3, 6}, std::array<int, 3>{1, 1, 2});
  CAPTURE(int(spec.stacking), int(spec.footprint), spec.cells[0], spec.cells[1], spec.cells[2]);
  const StrutGraph g = build_lattice(spec);
  const double L = spec.strut_length, h = parameter(g, "layer_height"), T = spec.plate_thickness;
  const std::vector<int> degree = node_degrees(g);
  std::map<long, int> tripods_per_layer;
  size_t carried_tops = 0, tops_below_last = 0;
  for (const auto& s : g.struts) {
    if (std::abs(strut_length(g, s) - 2 * L / 3) > 1e-9) continue;
    const int32_t node = g.nodes[s.a].z() < g.nodes[s.b].z() ? s.a : s.b;
    const int32_t top = node == s.a ? s.b : s.a;
    CHECK(std::abs(g.nodes[top].x() - g.nodes[node].x()) < 1e-12);  // vertical
    ++tripods_per_layer[std::lround((g.nodes[node].z() - T) / h - 0.5)];
    if (g.nodes[top].z() < T + spec.cells[2] * h - 1e-9) {
      ++tops_below_last;
      if (degree[top] > 1) ++carried_tops;  // a foot of the next layer lands on it
    }
  }
  REQUIRE(tripods_per_layer.size() == size_t(spec.cells[2]));
  for (const auto& [layer, count] : tripods_per_layer) CHECK(count == spec.cells[0] * spec.cells[1]);
  CHECK(tops_below_last == size_t(spec.cells[0] * spec.cells[1] * (spec.cells[2] - 1)));
  CHECK(carried_tops == tops_below_last);  // every vertical strut below the top carries feet
  CHECK(count_duplicate_nodes(g, 1e-6) == 0);
  CHECK(count_duplicate_struts(g) == 0);
  CHECK(count_bodies(g, 1e-9) == 1);
}

TEST_CASE("The 30 degree lattice spans about 66 by 59 mm as the decision predicts",
          "[geometry][lattice]") {
  // REFERENCE.md: nodes spread over ≈ 5a × 5a·√3/2 with a = √3·L cos φ; with the legs
  // ≈ 66 × 59 mm for φ = 30°.
  const StrutGraph g = build_lattice(preset_lattice("T2P30"));
  Eigen::AlignedBox3d nodes;
  for (const auto& n : g.nodes) nodes.extend(n);
  CHECK(nodes.sizes().x() == Approx(66e-3).margin(1e-3));
  CHECK(nodes.sizes().y() == Approx(59e-3).margin(1e-3));
  // The footprint is centred on the z axis.
  const Eigen::AlignedBox3d solid = solid_bounds(g, true);
  CHECK(std::abs(solid.center().x()) < 1e-12);
  CHECK(std::abs(solid.center().y()) < 1e-12);
}
