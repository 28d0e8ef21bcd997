// Strut groups (strut_partition.hpp): joint zones from the capsules' overlap, colours that
// keep same-coloured struts apart, and the points' tags from their nearest strut.
#include <catch2/catch.hpp>

#include <cmath>

#include "core/errors.hpp"
#include "voxelize/strut_partition.hpp"
#include "voxelize/voxelize.hpp"

using namespace latmpm;

namespace {
StrutGraph graph_of(const std::vector<Eigen::Vector3d>& nodes, const std::vector<std::pair<int, int>>& struts, double r) {
  StrutGraph g;
  g.name = "test";
  g.nodes = nodes;
  for (const auto& [a, b] : struts) g.struts.push_back({a, b, r});
  return g;
}
}  // namespace

TEST_CASE("A joint zone reaches as far as the capsules of the struts meeting there overlap", "[voxelize][strut_groups]") {
  // A V of two struts (r = 1 mm, 10 mm long) at 60° at node 0: two cylinders of radius r
  // whose axes open at θ stop overlapping r / sin(θ/2) = 2 mm from the node; a free end
  // has none; an end standing on a plate is glued there: its cap, r.
  const double r = 1e-3, theta = M_PI / 3;
  const StrutGraph v = graph_of({{0, 0, 0}, {10e-3, 0, 0}, {10e-3 * std::cos(theta), 10e-3 * std::sin(theta), 0}},
                                {{0, 1}, {0, 2}}, r);
  StrutGraph v_on_plate = v;
  v_on_plate.plates.push_back({"top_plate", {9e-3, -2e-3, -2e-3}, {12e-3, 2e-3, 2e-3}});  // holds node 1
  const StrutPartition p = partition_struts(v_on_plate, 4);
  CHECK(p.joint_radius[0] == Approx(r / std::sin(theta / 2)));
  CHECK(p.joint_radius[1] == Approx(r));
  CHECK(p.joint_radius[2] == 0);
  CHECK(p.colour[0] != p.colour[1]);  // they share a node
  // A narrow V: the overlap (r / sin 5° = 11.5 mm) is capped at 0.45 of the strut.
  const StrutGraph narrow = graph_of({{0, 0, 0}, {10e-3, 0, 0}, {10e-3 * std::cos(0.1745), 10e-3 * std::sin(0.1745), 0}},
                                     {{0, 1}, {0, 2}}, r);
  CHECK(partition_struts(narrow, 4).joint_radius[0] == Approx(4.5e-3));
  CHECK_THROWS_AS(partition_struts(v, 1), InputError);  // two struts at a node need two colours
}

TEST_CASE("Strut colours keep struts of one colour as far apart as the number of colours allows",
          "[voxelize][strut_groups]") {
  // Five parallel struts 4 mm apart in a row (surface gaps 2 mm, 6 mm, 10 mm, 14 mm for
  // neighbours 1, 2, 3, 4 apart): two colours alternate (same-colour gap 6 mm), three put
  // same colours three apart (10 mm), five colours give every strut its own.
  std::vector<Eigen::Vector3d> nodes;
  std::vector<std::pair<int, int>> struts;
  for (int i = 0; i < 5; ++i) {
    nodes.push_back({4e-3 * i, 0, 0});
    nodes.push_back({4e-3 * i, 0, 10e-3});
    struts.push_back({2 * i, 2 * i + 1});
  }
  const StrutGraph row = graph_of(nodes, struts, 1e-3);
  const StrutPartition two = partition_struts(row, 2);
  CHECK(two.colours == 2);
  CHECK(two.same_colour_gap == Approx(6e-3));
  const StrutPartition three = partition_struts(row, 3);
  CHECK(three.colours == 3);
  CHECK(three.same_colour_gap == Approx(10e-3));
  for (int i = 0; i + 1 < 5; ++i) CHECK(three.colour[size_t(i)] != three.colour[size_t(i + 1)]);
  const StrutPartition five = partition_struts(row, 5);
  CHECK(five.colours == 5);
  CHECK(std::isinf(five.same_colour_gap));
}

TEST_CASE("Points carry the colour of their nearest strut outside the joint zones", "[voxelize][strut_groups]") {
  // A T of three struts at node 0 (r = 0.8 mm): along +x, −x and +z, 8 mm each; h = 0.5 mm.
  const double r = 0.8e-3;
  const Eigen::Vector3d o(10e-3, 3e-3, 3e-3);
  const StrutGraph t = graph_of({o, o + Eigen::Vector3d(8e-3, 0, 0), o - Eigen::Vector3d(8e-3, 0, 0),
                                 o + Eigen::Vector3d(0, 0, 8e-3)},
                                {{0, 1}, {0, 2}, {0, 3}}, r);
  VoxelizeOptions options;
  options.cell_size = 0.5e-3;
  options.strut_groups = 3;
  const PointSet points = voxelize_strut_graph(t, options).points;
  const StrutPartition p = partition_struts(t, 3);
  REQUIRE(p.colours == 3);
  CHECK(points.parameters.at("strut_groups") == "3");
  size_t joint = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d d = points.position[i] - o;
    int tagged = 0, colour = -1;
    for (int c = 0; c < 3; ++c)
      if (points.tags.at(strut_group_tag(c))[i]) ++tagged, colour = c;
    CHECK(tagged <= 1);
    if (d.norm() < p.joint_radius[0]) {  // the joint: untagged
      CHECK(tagged == 0);
      ++joint;
      continue;
    }
    // Outside the joint (the end caps' radius r reaches no point of another strut), the
    // strut whose axis direction the point lies along.
    const int strut = d.z() > std::abs(d.x()) ? 2 : (d.x() > 0 ? 0 : 1);
    if (d.norm() > p.joint_radius[0] + r) CHECK(colour == p.colour[size_t(strut)]);
    if ((points.position[i] - t.nodes[1]).norm() < r) CHECK(tagged == 1);  // a free end is no joint
  }
  CHECK(joint > 0);
}
