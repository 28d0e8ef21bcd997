#include "voxelize/strut_partition.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "core/errors.hpp"
#include "core/units.hpp"

namespace latmpm {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

Kernel::Point_3 cgal_point(const Eigen::Vector3d& x) { return {x.x(), x.y(), x.z()}; }

double strut_length(const StrutGraph& g, const Strut& s) { return (g.nodes[size_t(s.b)] - g.nodes[size_t(s.a)]).norm(); }

// Surface gap of every pair of struts: axis-to-axis distance (CGAL) minus both radii.
struct Gap {
  size_t a, b;
  double gap;
};
std::vector<Gap> strut_gaps(const StrutGraph& g) {
  std::vector<Kernel::Segment_3> axes;
  for (const Strut& s : g.struts) axes.emplace_back(cgal_point(g.nodes[size_t(s.a)]), cgal_point(g.nodes[size_t(s.b)]));
  std::vector<Gap> gaps;
  for (size_t a = 0; a < axes.size(); ++a)
    for (size_t b = a + 1; b < axes.size(); ++b)
      gaps.push_back({a, b, std::sqrt(CGAL::to_double(CGAL::squared_distance(axes[a], axes[b]))) -
                                g.struts[a].radius - g.struts[b].radius});
  std::sort(gaps.begin(), gaps.end(), [](const Gap& x, const Gap& y) { return x.gap < y.gap; });
  return gaps;
}

// DSatur (Brélaz 1979) on the graph of the first `edges` pairs of `gaps`: colour per strut.
std::vector<int> dsatur(size_t struts, const std::vector<Gap>& gaps, size_t edges, int& colours) {
  std::vector<std::vector<size_t>> adjacent(struts);
  for (size_t e = 0; e < edges; ++e) adjacent[gaps[e].a].push_back(gaps[e].b), adjacent[gaps[e].b].push_back(gaps[e].a);
  std::vector<int> colour(struts, -1);
  std::vector<std::vector<char>> seen(struts);  // colours among the neighbours
  std::vector<int> saturation(struts, 0);
  colours = 0;
  for (size_t done = 0; done < struts; ++done) {
    size_t pick = struts;
    for (size_t v = 0; v < struts; ++v)
      if (colour[v] < 0 && (pick == struts || saturation[v] > saturation[pick] ||
                            (saturation[v] == saturation[pick] && adjacent[v].size() > adjacent[pick].size())))
        pick = v;
    int c = 0;
    while (c < int(seen[pick].size()) && seen[pick][size_t(c)]) ++c;
    colour[pick] = c;
    colours = std::max(colours, c + 1);
    for (size_t w : adjacent[pick]) {
      if (seen[w].size() <= size_t(c)) seen[w].resize(size_t(c) + 1, 0);
      if (!seen[w][size_t(c)]) seen[w][size_t(c)] = 1, ++saturation[w];
    }
  }
  return colour;
}

// Struts and nodes binned by their boxes on a uniform grid, for the points' look-ups.
class Bins {
 public:
  explicit Bins(double size) : size_(size) {}
  void add(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, size_t item) {
    const Eigen::Vector3i a = cell(lo), b = cell(hi);
    for (int i = a.x(); i <= b.x(); ++i)
      for (int j = a.y(); j <= b.y(); ++j)
        for (int k = a.z(); k <= b.z(); ++k) bins_[key({i, j, k})].push_back(item);
  }
  const std::vector<size_t>& at(const Eigen::Vector3d& x) const {
    static const std::vector<size_t> none;
    const auto it = bins_.find(key(cell(x)));
    return it == bins_.end() ? none : it->second;
  }

 private:
  Eigen::Vector3i cell(const Eigen::Vector3d& x) const { return (x / size_).array().floor().cast<int>(); }
  static int64_t key(const Eigen::Vector3i& c) {
    return (int64_t(c.x() & 0x1fffff) << 42) | (int64_t(c.y() & 0x1fffff) << 21) | int64_t(c.z() & 0x1fffff);
  }
  double size_;
  std::unordered_map<int64_t, std::vector<size_t>> bins_;
};

double capsule_distance(const StrutGraph& g, const Strut& s, const Eigen::Vector3d& x) {
  const Eigen::Vector3d a = g.nodes[size_t(s.a)], d = g.nodes[size_t(s.b)] - a;
  const double t = d.squaredNorm() > 0 ? std::clamp((x - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
  return (x - a - t * d).norm() - s.radius;
}

bool on_plate(const StrutGraph& g, const Eigen::Vector3d& x, double reach) {
  for (const Plate& plate : g.plates)
    if ((x.array() >= plate.min.array() - reach).all() && (x.array() <= plate.max.array() + reach).all()) return true;
  return false;
}

std::string millimetres(double metres) { return format_millimetres(metres, 4); }

}  // namespace

std::string strut_group_tag(int colour) { return strut_group_tag_prefix + std::to_string(colour); }

StrutPartition partition_struts(const StrutGraph& g, int max_colours) {
  if (max_colours < 1) throw InputError("strut groups", "colours", "must be at least 1");
  StrutPartition p;
  const size_t n = g.struts.size();
  // Joint zones.
  std::vector<std::vector<size_t>> at_node(g.nodes.size());
  for (size_t s = 0; s < n; ++s) at_node[size_t(g.struts[s].a)].push_back(s), at_node[size_t(g.struts[s].b)].push_back(s);
  p.joint_radius.assign(g.nodes.size(), 0.0);
  for (size_t v = 0; v < g.nodes.size(); ++v) {
    double radius = 0, shortest = std::numeric_limits<double>::infinity();
    const auto away = [&](size_t s) {  // unit vector from node v along strut s
      const Strut& t = g.struts[s];
      return (g.nodes[size_t(t.a == int32_t(v) ? t.b : t.a)] - g.nodes[v]).normalized();
    };
    for (size_t i = 0; i < at_node[v].size(); ++i) {
      const Strut& a = g.struts[at_node[v][i]];
      radius = std::max(radius, a.radius);
      shortest = std::min(shortest, strut_length(g, a));
      for (size_t j = i + 1; j < at_node[v].size(); ++j) {
        const Strut& b = g.struts[at_node[v][j]];
        const double half_angle = 0.5 * std::acos(std::clamp(away(at_node[v][i]).dot(away(at_node[v][j])), -1.0, 1.0));
        radius = std::max(radius, (a.radius + b.radius) / (2 * std::max(std::sin(half_angle), 1e-6)));
      }
    }
    // A strut's free end is no joint, unless it stands on a plate (its own body, glued there).
    if (at_node[v].size() == 1 && !on_plate(g, g.nodes[v], radius)) radius = 0;
    p.joint_radius[v] = std::min(radius, 0.45 * shortest);
  }
  // Colours: the largest conflict gap D that DSatur colours within max_colours.
  const std::vector<Gap> gaps = strut_gaps(g);
  size_t must = 0;  // pairs sharing a node come first (their gap is −r_a − r_b ≤ any other)
  auto shares_node = [&](const Gap& e) {
    const Strut &a = g.struts[e.a], &b = g.struts[e.b];
    return a.a == b.a || a.a == b.b || a.b == b.a || a.b == b.b;
  };
  for (size_t e = 0; e < gaps.size(); ++e)
    if (shares_node(gaps[e])) must = e + 1;
  int colours = 0;
  p.colour = dsatur(n, gaps, must, colours);
  if (colours > max_colours)
    throw InputError("strut groups", "colours", "the struts meeting at the nodes need " + std::to_string(colours) +
                                                    " colours, more than " + std::to_string(max_colours));
  p.colours = colours;
  size_t lo = must, hi = gaps.size();  // lo: feasible edge count; find the largest
  while (lo < hi) {
    const size_t mid = lo + (hi - lo + 1) / 2;
    int c = 0;
    std::vector<int> colour = dsatur(n, gaps, mid, c);
    if (c <= max_colours)
      lo = mid, p.colour = std::move(colour), p.colours = c;
    else
      hi = mid - 1;
  }
  p.same_colour_gap = std::numeric_limits<double>::infinity();
  for (const Gap& e : gaps)
    if (p.colour[e.a] == p.colour[e.b]) {
      p.same_colour_gap = e.gap;
      break;
    }
  return p;
}

void tag_strut_groups(PointSet& points, const StrutGraph& g, const StrutPartition& p) {
  const int body = points.body_index(g.strut_body);
  const size_t count = points.size();
  std::vector<std::vector<uint8_t>*> tags;
  for (int c = 0; c < p.colours; ++c) {
    auto& tag = points.tags[strut_group_tag(c)];
    tag.assign(count, 0);
    tags.push_back(&tag);
  }
  if (body < 0 || g.struts.empty()) return;
  double longest = 0;
  for (const Strut& s : g.struts) longest = std::max(longest, strut_length(g, s));
  const double reach = points.cell_size / std::max(points.ppc, 1);  // surface points lie within a spacing
  Bins struts(std::max(longest / 4, 1e-9)), nodes(std::max(longest / 4, 1e-9));
  for (size_t s = 0; s < g.struts.size(); ++s) {
    const Eigen::Vector3d a = g.nodes[size_t(g.struts[s].a)], b = g.nodes[size_t(g.struts[s].b)];
    const Eigen::Vector3d pad = Eigen::Vector3d::Constant(g.struts[s].radius + reach);
    struts.add(a.cwiseMin(b) - pad, a.cwiseMax(b) + pad, s);
  }
  for (size_t v = 0; v < g.nodes.size(); ++v)
    if (p.joint_radius[v] > 0) {
      const Eigen::Vector3d pad = Eigen::Vector3d::Constant(p.joint_radius[v]);
      nodes.add(g.nodes[v] - pad, g.nodes[v] + pad, v);
    }
  for (size_t i = 0; i < count; ++i) {
    if (points.body[i] != body) continue;
    const Eigen::Vector3d& x = points.position[i];
    bool joint = false;
    for (size_t v : nodes.at(x)) joint = joint || (x - g.nodes[v]).norm() < p.joint_radius[v];
    if (joint) continue;
    size_t nearest = g.struts.size();
    double best = std::numeric_limits<double>::infinity();
    const std::vector<size_t>& near = struts.at(x);
    const auto consider = [&](size_t s) {
      const double d = capsule_distance(g, g.struts[s], x);
      if (d < best) best = d, nearest = s;
    };
    for (size_t s : near) consider(s);
    if (nearest == g.struts.size())  // outside every padded box: ask every strut
      for (size_t s = 0; s < g.struts.size(); ++s) consider(s);
    (*tags[size_t(p.colour[nearest])])[i] = 1;
  }
  points.parameters["strut_groups"] = std::to_string(p.colours);
  points.parameters["strut_group_gap"] =
      std::isfinite(p.same_colour_gap) ? millimetres(p.same_colour_gap) : std::string("none (every strut its own colour)");
}

}  // namespace latmpm
