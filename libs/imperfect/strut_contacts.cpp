#include "imperfect/strut_contacts.hpp"

#include <algorithm>
#include <cmath>

namespace latmpm {

double segment_distance(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& q0,
                        const Eigen::Vector3d& q1, Eigen::Vector3d* midpoint) {
  const Eigen::Vector3d d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  const double tiny = 1e-300;
  double s = 0, t = 0;
  if (a <= tiny && e <= tiny) {
    s = t = 0;
  } else if (a <= tiny) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = d1.dot(r);
    if (e <= tiny) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = d1.dot(d2), denom = a * e - b * b;
      s = denom > 0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0) {
        t = 0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1) {
        t = 1;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  const Eigen::Vector3d cp = p0 + s * d1, cq = q0 + t * d2;
  if (midpoint) *midpoint = 0.5 * (cp + cq);
  return (cp - cq).norm();
}

std::map<std::pair<int, int>, Eigen::Vector3d> touching_members(const StrutGraph& graph,
                                                                const std::vector<MemberChain>& chains) {
  const size_t m = chains.size();
  std::vector<Eigen::Vector3d> lo(m), hi(m);
  std::vector<double> radius(m, 0);
  for (size_t i = 0; i < m; ++i) {
    lo[i] = hi[i] = graph.nodes[chains[i].nodes[0]];
    for (int32_t n : chains[i].nodes) {
      lo[i] = lo[i].cwiseMin(graph.nodes[n]);
      hi[i] = hi[i].cwiseMax(graph.nodes[n]);
    }
    for (int32_t s : chains[i].struts) radius[i] = std::max(radius[i], graph.struts[s].radius);
  }
  // Sweep along x over the members' boxes (sorted by their low x end).
  std::vector<size_t> order(m);
  for (size_t i = 0; i < m; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return lo[a].x() - radius[a] < lo[b].x() - radius[b]; });

  std::map<std::pair<int, int>, Eigen::Vector3d> touching;
  for (size_t oi = 0; oi < m; ++oi) {
    const size_t i = order[oi];
    for (size_t oj = oi + 1; oj < m; ++oj) {
      const size_t j = order[oj];
      const double gap = radius[i] + radius[j];
      if (lo[j].x() - radius[j] > hi[i].x() + radius[i]) break;
      if (((lo[j].array() - gap) > hi[i].array()).any() || ((lo[i].array() - gap) > hi[j].array()).any()) continue;
      const auto& ni = chains[i].nodes;
      const auto& nj = chains[j].nodes;
      if (std::find_first_of(ni.begin(), ni.end(), nj.begin(), nj.end()) != ni.end()) continue;
      bool found = false;
      for (int32_t si : chains[i].struts) {
        for (int32_t sj : chains[j].struts) {
          const Strut &a = graph.struts[si], &b = graph.struts[sj];
          Eigen::Vector3d where;
          if (segment_distance(graph.nodes[a.a], graph.nodes[a.b], graph.nodes[b.a], graph.nodes[b.b], &where) <
              a.radius + b.radius) {
            touching.emplace(std::make_pair(static_cast<int>(std::min(i, j)), static_cast<int>(std::max(i, j))), where);
            found = true;
            break;
          }
        }
        if (found) break;
      }
    }
  }
  return touching;
}

}  // namespace latmpm
