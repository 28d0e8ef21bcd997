#include <catch2/catch.hpp>

#include <cmath>
#include <set>

#include "core/errors.hpp"
#include "geometry/lattice.hpp"
#include "geometry/graph_checks.hpp"
#include "imperfect/strut_contacts.hpp"
#include "imperfect/strut_defects.hpp"

using namespace latmpm;

namespace {

// The paper's T1P40 specimen (5 × 5 × 5 cells, 3 mm plates), or a wider one for statistics.
MemberGraph t1p40(int cells_across = 5) {
  LatticeSpec spec = preset_lattice("T1P40");
  spec.cells = {cells_across, cells_across, 5};
  MemberGraph g{build_lattice(spec), {}};
  g.member = one_member_per_strut(g.graph);
  return g;
}

// Four standard errors of a sample mean of n draws with standard deviation sd.
double four_standard_errors(double sd, size_t n) { return 4 * sd / std::sqrt(double(n)); }

bool same_graph(const MemberGraph& a, const MemberGraph& b) {
  if (a.graph.nodes != b.graph.nodes || a.member != b.member || a.graph.struts.size() != b.graph.struts.size()) return false;
  for (size_t s = 0; s < a.graph.struts.size(); ++s) {
    const Strut &x = a.graph.struts[s], &y = b.graph.struts[s];
    if (x.a != y.a || x.b != y.b || x.radius != y.radius) return false;
  }
  return true;
}

MemberGraph all_defects(uint64_t seed) {
  MemberGraph g = t1p40();
  RandomStream r1(seed, 1), r2(seed, 2), r3(seed, 3), r4(seed, 4);
  scatter_strut_diameters(g, {0.05, 0.02, false}, r1, "--strut-diameter-cov", "t1p40");
  add_waviness(g, {0.01, 3, 8}, r2, "--waviness", "t1p40");
  jitter_nodes(g, {0.05e-3}, r3, "--node-jitter", "t1p40");
  remove_struts(g, {0.01, OnDisconnected::keep}, r4, "--missing-struts", "t1p40");
  return g;
}

}  // namespace

TEST_CASE("The same seed gives the same defects, another seed different ones", "[imperfect][defects]") {
  CHECK(same_graph(all_defects(7), all_defects(7)));
  CHECK_FALSE(same_graph(all_defects(7), all_defects(8)));
}

TEST_CASE("Strut diameters scatter with the requested mean and coefficient of variation", "[imperfect][defects]") {
  const bool normal = GENERATE(false, true);
  const double cov = 0.08, bias = 0.03;
  MemberGraph g = t1p40(10);
  const double designed = 2 * g.graph.struts[0].radius;
  RandomStream random(11, 1);
  scatter_strut_diameters(g, {cov, bias, normal}, random, "--strut-diameter-cov", "t1p40");
  const auto [mean, sample_cov] = member_diameter_statistics(g, "t1p40");
  const size_t n = g.graph.struts.size();
  INFO((normal ? "normal" : "lognormal") << ", " << n << " struts");
  REQUIRE(n > 1500);
  const double expected_mean = (1 + bias) * designed, expected_sd = cov * expected_mean;
  CHECK(std::abs(mean - expected_mean) <= four_standard_errors(expected_sd, n));
  // The sample sd of n draws has a standard error of about sd / sqrt(2 (n - 1)).
  CHECK(std::abs(sample_cov - cov) <= 4 * cov / std::sqrt(2.0 * (n - 1)) + cov * four_standard_errors(cov, n));
  for (const Strut& s : g.graph.struts) REQUIRE(s.radius > 0);
}

TEST_CASE("Waviness deflects strut middles by the requested amplitude and keeps strut ends in place",
          "[imperfect][defects]") {
  const double w = 0.02;
  const MemberGraph before = t1p40(10);
  MemberGraph g = before;
  RandomStream random(3, 1);
  add_waviness(g, {w, 3, 8}, random, "--waviness", "t1p40");
  std::vector<int32_t> member = g.member;
  const auto chains = member_chains(g.graph, member, "t1p40");
  REQUIRE(chains.size() == before.graph.struts.size());
  CHECK(g.graph.struts.size() == 8 * before.graph.struts.size());
  // At mid-length sin(k pi / 2) = 1, 0, -1 for k = 1, 2, 3, so each lateral component of the
  // deflection has variance (w l)^2 (1 + 1/3^4).
  double sum2 = 0;
  size_t samples = 0;
  for (size_t m = 0; m < chains.size(); ++m) {
    const auto& c = chains[m];
    REQUIRE(c.nodes.size() == 9);
    const Strut& original = before.graph.struts[m];
    const Eigen::Vector3d a = before.graph.nodes[original.a], b = before.graph.nodes[original.b];
    REQUIRE(g.graph.nodes[c.nodes.front()] == (c.nodes.front() == original.a ? a : b));
    REQUIRE(g.graph.nodes[c.nodes.back()] == (c.nodes.back() == original.b ? b : a));
    const double length = (b - a).norm();
    const Eigen::Vector3d straight = 0.5 * (a + b), t = (b - a) / length;
    const Eigen::Vector3d deflection = g.graph.nodes[c.nodes[4]] - straight;
    REQUIRE(std::abs(deflection.dot(t)) <= 1e-12);
    sum2 += deflection.squaredNorm() / (length * length);
    samples += 2;  // two lateral components
  }
  const double expected = w * w * (1 + 1.0 / 81);
  // Variance estimate from `samples` normal draws: relative standard error sqrt(2 / samples).
  CHECK(std::abs(sum2 / samples - expected) <= 4 * expected * std::sqrt(2.0 / samples));
}

TEST_CASE("Node jitter moves junctions with the requested spread and keeps plate nodes on the plate",
          "[imperfect][defects]") {
  const double sigma = 0.05e-3;
  const MemberGraph before = t1p40(10);
  MemberGraph g = before;
  RandomStream random(5, 1);
  jitter_nodes(g, {sigma}, random, "--node-jitter", "t1p40");
  double sum2 = 0;
  size_t samples = 0, on_plate = 0;
  for (size_t n = 0; n < g.graph.nodes.size(); ++n) {
    const Eigen::Vector3d u = g.graph.nodes[n] - before.graph.nodes[n];
    bool held = false;
    for (const Plate& p : before.graph.plates)
      held = held || distance_to_box(before.graph.nodes[n], p.min, p.max) <= 1e-9;
    if (held) {
      ++on_plate;
      REQUIRE(u.z() == 0.0);
      continue;
    }
    sum2 += u.squaredNorm();
    samples += 3;
  }
  CHECK(on_plate > 0);
  CHECK(std::abs(sum2 / samples - sigma * sigma) <= 4 * sigma * sigma * std::sqrt(2.0 / samples));
}

TEST_CASE("Jitter after waviness carries a wavy strut's interior with its ends", "[imperfect][defects]") {
  MemberGraph g = t1p40();
  RandomStream r1(2, 1), r2(2, 2);
  add_waviness(g, {0.01, 3, 4}, r1, "--waviness", "t1p40");
  const MemberGraph wavy = g;
  jitter_nodes(g, {0.05e-3}, r2, "--node-jitter", "t1p40");
  std::vector<int32_t> member = g.member;
  for (const auto& c : member_chains(g.graph, member, "t1p40")) {
    auto move = [&](int32_t n) { return Eigen::Vector3d(g.graph.nodes[n] - wavy.graph.nodes[n]); };
    std::vector<double> s{0};
    for (size_t i = 1; i < c.nodes.size(); ++i)
      s.push_back(s.back() + (wavy.graph.nodes[c.nodes[i]] - wavy.graph.nodes[c.nodes[i - 1]]).norm());
    for (size_t i = 1; i + 1 < c.nodes.size(); ++i) {
      const double f = s[i] / s.back();
      REQUIRE((move(c.nodes[i]) - ((1 - f) * move(c.nodes.front()) + f * move(c.nodes.back()))).norm() <= 1e-15);
    }
  }
}

TEST_CASE("Diameter scatter after waviness gives every segment of a strut the same diameter", "[imperfect][defects]") {
  MemberGraph g = t1p40();
  RandomStream r1(4, 1), r2(4, 2);
  add_waviness(g, {0.01, 3, 8}, r1, "--waviness", "t1p40");
  scatter_strut_diameters(g, {0.1, 0, false}, r2, "--strut-diameter-cov", "t1p40");
  std::vector<int32_t> member = g.member;
  for (const auto& c : member_chains(g.graph, member, "t1p40"))
    for (int32_t s : c.struts) REQUIRE(g.graph.struts[s].radius == g.graph.struts[c.struts[0]].radius);
}

TEST_CASE("Missing struts: the requested fraction goes, and the rest is one body or the removal is refused",
          "[imperfect][defects]") {
  const double fraction = 0.03;
  const MemberGraph before = t1p40(10);
  const size_t expected_removed = static_cast<size_t>(std::llround(fraction * before.graph.struts.size()));
  int accepted = 0, refused = 0;
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    MemberGraph g = before;
    RandomStream random(seed, 1);
    try {
      remove_struts(g, {fraction, OnDisconnected::refuse}, random, "--missing-struts", "t1p40");
      ++accepted;
      CHECK(before.graph.struts.size() - g.graph.struts.size() == expected_removed);
      CHECK(connected_pieces(g.graph).count == 1);
    } catch (const InputError& e) {
      ++refused;
      CHECK_THAT(e.what(), Catch::StartsWith("--missing-struts") && Catch::Contains("separate pieces"));
      CHECK(same_graph(g, before));  // nothing half-done
    }
  }
  INFO(accepted << " accepted, " << refused << " refused");
  CHECK(accepted > 0);
}

TEST_CASE("Removing struts that cut a chain is refused, dropped or kept as asked", "[imperfect][defects]") {
  // A straight chain of ten struts standing on a plate: any removal cuts it.
  MemberGraph g;
  for (int i = 0; i <= 10; ++i) g.graph.nodes.push_back({0, 0, 1e-3 * i});
  for (int i = 0; i < 10; ++i) g.graph.struts.push_back({i, i + 1, 0.2e-3});
  g.graph.plates.push_back({"bottom_plate", {-2e-3, -2e-3, -1e-3}, {2e-3, 2e-3, 0}});
  g.member = one_member_per_strut(g.graph);
  const MemberGraph before = g;
  {
    RandomStream random(1, 1);
    CHECK_THROWS_WITH(remove_struts(g, {0.2, OnDisconnected::refuse}, random, "--missing-struts", "chain"),
                      Catch::StartsWith("--missing-struts"));
  }
  {
    RandomStream random(1, 1);
    MemberGraph dropped = before;
    remove_struts(dropped, {0.2, OnDisconnected::drop}, random, "--missing-struts", "chain");
    CHECK(connected_pieces(dropped.graph).count == 1);
    CHECK(dropped.graph.struts.size() < 8);
  }
  {
    RandomStream random(1, 1);
    MemberGraph kept = before;
    const DefectResult r = remove_struts(kept, {0.2, OnDisconnected::keep}, random, "--missing-struts", "chain");
    CHECK(kept.graph.struts.size() == 8);
    CHECK(connected_pieces(kept.graph).count > 1);
    CHECK_FALSE(r.notes.empty());
  }
}

TEST_CASE("Defects so large that struts would cross are refused and leave the graph as it was", "[imperfect][defects]") {
  const MemberGraph before = t1p40();
  MemberGraph g = before;
  RandomStream r1(1, 1), r2(1, 2);
  CHECK_THROWS_WITH(add_waviness(g, {0.25, 3, 8}, r1, "--waviness", "t1p40"),
                    Catch::StartsWith("--waviness") && Catch::Contains("cross"));
  CHECK_THROWS_WITH(jitter_nodes(g, {3e-3}, r2, "--node-jitter", "t1p40"),
                    Catch::StartsWith("--node-jitter") && Catch::Contains("cross"));
  CHECK(same_graph(g, before));
}

TEST_CASE("The T1P40 specimen is one body whose struts touch only where they share a node", "[imperfect][defects]") {
  // The premise of the crossing criterion: the undisturbed lattice has no other contacts.
  MemberGraph g = t1p40();
  CHECK(connected_pieces(g.graph).count == 1);
  std::vector<int32_t> member = g.member;
  CHECK(touching_members(g.graph, member_chains(g.graph, member, "t1p40")).empty());
}
