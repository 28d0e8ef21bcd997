#include "core/units.hpp"
#include "imperfect/strut_defects.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>
#include <sstream>

#include "core/errors.hpp"
#include "geometry/graph_checks.hpp"
#include "imperfect/strut_contacts.hpp"

namespace latmpm {
namespace {

std::string percent(double fraction) {
  std::ostringstream os;
  os.precision(4);
  os << fraction * 100 << " %";
  return os.str();
}

std::string mm(double metres) { return format_millimetres(metres, 5); }

std::string point_mm(const Eigen::Vector3d& x) {
  std::ostringstream os;
  os.precision(4);
  os << "(" << x.x() * 1e3 << ", " << x.y() * 1e3 << ", " << x.z() * 1e3 << ") mm";
  return os.str();
}

// Fraction of the way along a chain at each of its nodes, by the current segment lengths.
std::vector<double> chain_parameter(const StrutGraph& graph, const MemberChain& chain) {
  std::vector<double> s(chain.nodes.size(), 0.0);
  for (size_t i = 1; i < chain.nodes.size(); ++i)
    s[i] = s[i - 1] + (graph.nodes[chain.nodes[i]] - graph.nodes[chain.nodes[i - 1]]).norm();
  const double total = s.back();
  for (auto& v : s) v = total > 0 ? v / total : 0.0;
  return s;
}

// Refuses a geometry change that makes members touch that were apart (struts would cross).
void refuse_new_contacts(const StrutGraph& before, const StrutGraph& after, const std::vector<MemberChain>& chains_before,
                         const std::vector<MemberChain>& chains_after, const std::string& option,
                         const std::string& what) {
  const auto was = touching_members(before, chains_before);
  const auto now = touching_members(after, chains_after);
  size_t added = 0;
  const std::pair<const std::pair<int, int>, Eigen::Vector3d>* first = nullptr;
  for (const auto& entry : now)
    if (!was.count(entry.first)) {
      if (!first) first = &entry;
      ++added;
    }
  if (added == 0) return;
  throw InputError(option, "", what + " makes " + std::to_string(added) + " pair(s) of struts touch that were apart (first: struts " +
                                   std::to_string(first->first.first) + " and " + std::to_string(first->first.second) + " near " +
                                   point_mm(first->second) + "), so struts would cross; lower it or change --seed");
}

// Removes nodes no strut uses any more (that some strut used before) and renumbers.
void drop_orphan_nodes(StrutGraph& graph, const std::vector<bool>& used_before) {
  std::vector<bool> used(graph.nodes.size(), false);
  for (const Strut& s : graph.struts) used[s.a] = used[s.b] = true;
  std::vector<int32_t> renumber(graph.nodes.size(), -1);
  std::vector<Eigen::Vector3d> kept;
  for (size_t n = 0; n < graph.nodes.size(); ++n)
    if (used[n] || !used_before[n]) {
      renumber[n] = static_cast<int32_t>(kept.size());
      kept.push_back(graph.nodes[n]);
    }
  graph.nodes = std::move(kept);
  for (Strut& s : graph.struts) {
    s.a = renumber[s.a];
    s.b = renumber[s.b];
  }
}

}  // namespace

std::pair<double, double> member_diameter_statistics(const MemberGraph& g, const std::string& where) {
  std::vector<int32_t> member = g.member;
  const auto chains = member_chains(g.graph, member, where);
  if (chains.empty()) return {0, 0};
  double sum = 0, sum2 = 0;
  for (const auto& c : chains) {
    const double d = 2 * g.graph.struts[c.struts[0]].radius;
    sum += d;
    sum2 += d * d;
  }
  const double n = static_cast<double>(chains.size()), mean = sum / n;
  const double variance = chains.size() > 1 ? std::max(0.0, (sum2 - n * mean * mean) / (n - 1)) : 0.0;
  return {mean, std::sqrt(variance) / mean};
}

DefectResult scatter_strut_diameters(MemberGraph& g, const DiameterScatter& d, RandomStream& random,
                                     const std::string& option, const std::string& where) {
  if (!(d.cov >= 0 && d.cov < 1)) throw InputError(option, "", "the coefficient of variation must lie in [0 %, 100 %)");
  if (!(d.bias > -1 && d.bias < 1)) throw InputError("--strut-diameter-bias", "", "the mean change must lie in (-100 %, 100 %)");
  const auto chains = member_chains(g.graph, g.member, where);
  const double mean = 1 + d.bias;
  // Lognormal with mean m and CoV c: ln X ~ N(ln m − σ²/2, σ²), σ² = ln(1 + c²).
  const double sigma = std::sqrt(std::log1p(d.cov * d.cov)), mu = std::log(mean) - 0.5 * sigma * sigma;
  for (const auto& chain : chains) {
    double factor;
    if (d.normal) {
      do factor = mean * (1 + d.cov * random.normal());
      while (!(factor > 0));
    } else {
      factor = std::exp(mu + sigma * random.normal());
    }
    for (int32_t s : chain.struts) g.graph.struts[s].radius *= factor;
  }
  const auto [mean_d, cov_d] = member_diameter_statistics(g, where);
  DefectResult r;
  std::ostringstream os;
  os << "strut diameters: " << (d.normal ? "normal" : "lognormal") << " factor, mean " << percent(mean) << ", CoV "
     << percent(d.cov) << ", " << chains.size() << " struts; now mean " << mm(mean_d) << ", CoV " << percent(cov_d);
  r.record = os.str();
  return r;
}

DefectResult add_waviness(MemberGraph& g, const Waviness& w, RandomStream& random, const std::string& option,
                          const std::string& where) {
  if (!(w.amplitude >= 0 && w.amplitude <= 0.25))
    throw InputError(option, "", "the waviness must lie in [0 %, 25 %] of the strut length");
  if (w.modes < 1 || w.modes > 16) throw InputError("--waviness-modes", "", "must be 1 to 16");
  if (w.segments < 2 || w.segments > 64) throw InputError("--waviness-segments", "", "must be 2 to 64");
  const auto chains_before = member_chains(g.graph, g.member, where);
  MemberGraph out = g;  // g changes only if the result is accepted

  // 1. Split straight members (one segment) into `segments` capsules along their axis.
  StrutGraph& graph = out.graph;
  std::vector<Strut> struts;
  std::vector<int32_t> member;
  size_t split = 0;
  for (size_t s = 0; s < graph.struts.size(); ++s) {
    const int32_t m = out.member[s];
    if (chains_before[m].struts.size() > 1) {
      struts.push_back(graph.struts[s]);
      member.push_back(m);
      continue;
    }
    ++split;
    const Strut st = graph.struts[s];
    const Eigen::Vector3d a = graph.nodes[st.a], b = graph.nodes[st.b];
    int32_t previous = st.a;
    for (int k = 1; k <= w.segments; ++k) {
      int32_t next = st.b;
      if (k < w.segments) {
        next = static_cast<int32_t>(graph.nodes.size());
        graph.nodes.push_back(a + (b - a) * (double(k) / w.segments));
      }
      struts.push_back({previous, next, st.radius});
      member.push_back(m);
      previous = next;
    }
  }
  graph.struts = std::move(struts);
  out.member = std::move(member);
  const auto chains = member_chains(graph, out.member, where);

  // 2. Deflect the interior nodes of every member.
  double largest = 0;
  for (const auto& chain : chains) {
    const Eigen::Vector3d a = graph.nodes[chain.nodes.front()], b = graph.nodes[chain.nodes.back()];
    const double length = (b - a).norm();
    const Eigen::Vector3d t = (b - a) / length;
    const Eigen::Vector3d helper = std::abs(t.z()) < 0.9 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitX();
    const Eigen::Vector3d n1 = t.cross(helper).normalized(), n2 = t.cross(n1);
    std::vector<Eigen::Vector2d> amplitude(w.modes);
    for (int k = 1; k <= w.modes; ++k) {
      const double sd = w.amplitude * length / (double(k) * k);
      const double alpha = sd * random.normal(), beta = sd * random.normal();
      amplitude[k - 1] = {alpha, beta};
    }
    const auto s = chain_parameter(graph, chain);
    for (size_t i = 1; i + 1 < chain.nodes.size(); ++i) {
      Eigen::Vector2d delta = Eigen::Vector2d::Zero();
      for (int k = 1; k <= w.modes; ++k) delta += amplitude[k - 1] * std::sin(k * M_PI * s[i]);
      graph.nodes[chain.nodes[i]] += delta.x() * n1 + delta.y() * n2;
      largest = std::max(largest, delta.norm() / length);
    }
  }
  refuse_new_contacts(g.graph, graph, chains_before, chains, option, "waviness " + percent(w.amplitude));
  g = std::move(out);

  DefectResult r;
  std::ostringstream os;
  os << "waviness: amplitude " << percent(w.amplitude) << " of strut length (mode k sd amplitude/k^2), " << w.modes
     << " modes, " << split << " struts split into " << w.segments << " segments; largest deflection "
     << percent(largest) << " of a strut length";
  r.record = os.str();
  return r;
}

DefectResult jitter_nodes(MemberGraph& g, const NodeJitter& j, RandomStream& random, const std::string& option,
                          const std::string& where) {
  if (!(j.sigma >= 0) || !std::isfinite(j.sigma)) throw InputError(option, "", "must be zero or positive");
  const StrutGraph& before = g.graph;
  const auto chains = member_chains(g.graph, g.member, where);
  StrutGraph graph = g.graph;  // g changes only if the result is accepted

  // Junctions: member ends, in node order so the draws do not depend on member order.
  std::set<int32_t> junctions;
  for (const auto& c : chains) junctions.insert({c.nodes.front(), c.nodes.back()});
  std::vector<Eigen::Vector3d> move(graph.nodes.size(), Eigen::Vector3d::Zero());
  const double on_plate = 1e-9;  // m: a node this close to a plate box sits on it
  size_t held = 0;
  for (int32_t n : junctions) {
    Eigen::Vector3d delta(random.normal(), random.normal(), random.normal());
    delta *= j.sigma;
    for (const Plate& p : graph.plates) {
      const Eigen::Vector3d x = graph.nodes[n];
      if (distance_to_box(x, p.min, p.max) > on_plate) continue;
      // Keep the component normal to the nearest face of the plate: the node stays on it.
      Eigen::Vector3d to_min = (x - p.min).cwiseAbs(), to_max = (p.max - x).cwiseAbs();
      Eigen::Index axis_min, axis_max;
      const double dmin = to_min.minCoeff(&axis_min), dmax = to_max.minCoeff(&axis_max);
      delta[dmin <= dmax ? axis_min : axis_max] = 0;
      ++held;
      break;
    }
    move[n] = delta;
  }
  for (const auto& c : chains) {
    const auto s = chain_parameter(before, c);
    for (size_t i = 1; i + 1 < c.nodes.size(); ++i)
      move[c.nodes[i]] = (1 - s[i]) * move[c.nodes.front()] + s[i] * move[c.nodes.back()];
  }
  for (size_t n = 0; n < graph.nodes.size(); ++n) graph.nodes[n] += move[n];
  refuse_new_contacts(before, graph, chains, chains, option, "node jitter " + mm(j.sigma));
  g.graph = std::move(graph);

  DefectResult r;
  std::ostringstream os;
  os << "node jitter: Gaussian, sd " << mm(j.sigma) << " per axis, " << junctions.size() << " junction nodes, " << held
     << " of them on a plate kept on its face";
  r.record = os.str();
  return r;
}

DefectResult remove_struts(MemberGraph& g, const MissingStruts& m, RandomStream& random, const std::string& option,
                           const std::string& where) {
  if (!(m.fraction >= 0 && m.fraction < 1)) throw InputError(option, "", "the fraction must lie in [0 %, 100 %)");
  const auto chains = member_chains(g.graph, g.member, where);
  const size_t members = chains.size();
  const size_t removed = static_cast<size_t>(std::llround(m.fraction * static_cast<double>(members)));
  // Partial Fisher–Yates: the first `removed` entries are a uniform random subset.
  std::vector<int32_t> order(members);
  std::iota(order.begin(), order.end(), 0);
  for (size_t i = 0; i < removed; ++i) std::swap(order[i], order[i + random.below(members - i)]);
  std::vector<bool> gone(members, false);
  for (size_t i = 0; i < removed; ++i) gone[order[i]] = true;

  MemberGraph out = g;  // g changes only if the result is accepted
  StrutGraph& graph = out.graph;
  std::vector<bool> used_before(graph.nodes.size(), false);
  for (const Strut& s : graph.struts) used_before[s.a] = used_before[s.b] = true;
  auto keep_struts = [&](const std::vector<bool>& keep) {
    std::vector<Strut> struts;
    std::vector<int32_t> member;
    for (size_t s = 0; s < graph.struts.size(); ++s)
      if (keep[s]) {
        struts.push_back(graph.struts[s]);
        member.push_back(out.member[s]);
      }
    graph.struts = std::move(struts);
    out.member = std::move(member);
  };
  std::vector<bool> keep(graph.struts.size());
  for (size_t s = 0; s < graph.struts.size(); ++s) keep[s] = !gone[out.member[s]];
  keep_struts(keep);

  DefectResult r;
  std::ostringstream os;
  os << "missing struts: " << removed << " of " << members << " struts removed (" << percent(double(removed) / members)
     << ", asked " << percent(m.fraction) << ")";
  Pieces pieces = connected_pieces(graph);
  if (pieces.count > 1) {
    // The main piece: the one holding the plates (a body clamped between them), or the
    // largest without plates.
    int main = static_cast<int>(std::max_element(pieces.struts_in.begin(), pieces.struts_in.end()) - pieces.struts_in.begin());
    bool plates_together = true;
    if (!pieces.of_plate.empty()) {
      main = pieces.of_plate.front();
      for (int p : pieces.of_plate) plates_together = plates_together && p == main;
    }
    const size_t total = graph.struts.size();
    std::ostringstream pieces_text;
    pieces_text << pieces.count << " separate pieces (the main one holds "
                << percent(total ? double(pieces.struts_in[main]) / total : 0.0) << " of the strut segments)";
    std::ostringstream state;
    state << "the rest is " << pieces_text.str();
    if (m.on_disconnected == OnDisconnected::refuse || (m.on_disconnected == OnDisconnected::drop && !plates_together))
      throw InputError(option, "", "removing " + std::to_string(removed) + " struts leaves " + pieces_text.str() +
                                       (plates_together ? "" : ", and the plates are no longer joined through the lattice") + "; change --seed" +
                                       (plates_together ? " or use --disconnected drop|keep" : " or use --disconnected keep"));
    if (m.on_disconnected == OnDisconnected::drop) {
      std::vector<bool> on_main(graph.struts.size());
      for (size_t s = 0; s < graph.struts.size(); ++s) on_main[s] = pieces.of_strut[s] == main;
      const size_t loose = total - pieces.struts_in[main];
      keep_struts(on_main);
      os << "; " << state.str() << ": dropped the " << loose << " loose strut segments";
    } else {
      os << "; " << state.str() << ", kept as they are";
      r.notes.push_back("the result is not one connected body: " + state.str());
    }
  } else {
    os << "; still one connected body";
  }
  drop_orphan_nodes(graph, used_before);
  g = std::move(out);
  r.record = os.str();
  return r;
}

}  // namespace latmpm
