#include "post/impact_metrics.hpp"

#include <algorithm>
#include <cmath>

#include "post/curve.hpp"

namespace latmpm::post {

ImpactMetrics impact_metrics(const ImpactHistory& h) {
  ImpactMetrics m;
  const size_t n = h.time.size();
  if (n < 2) {
    m.notes.push_back("fewer than two rows: no impact metrics");
    return m;
  }
  m.final_time = h.time.back();
  if (h.load.size() == n) {
    const size_t peak = argmax(h.load);
    m.peak_load = h.load[peak];
    m.peak_time = h.time[peak];
  }
  if (h.velocity.size() != n) {
    m.notes.push_back("no flyer_velocity column: no reversal time, rebound speed or flyer energy");
    return m;
  }

  // Positive along the flyer's initial direction of motion.
  double sign = 0;
  for (double v : h.velocity)
    if (v != 0) {
      sign = v > 0 ? 1 : -1;
      break;
    }
  if (sign == 0) {
    m.notes.push_back("flyer_velocity is zero throughout: no reversal");
    return m;
  }
  std::vector<double> v(n);
  for (size_t i = 0; i < n; ++i) v[i] = sign * h.velocity[i];
  m.impact_speed = v.front();

  for (size_t i = 1; i < n; ++i)
    if (v[i - 1] > 0 && v[i] <= 0) {
      const double w = v[i - 1] / (v[i - 1] - v[i]);
      m.reversal_time = h.time[i - 1] + w * (h.time[i] - h.time[i - 1]);
      double rebound = 0;
      for (size_t j = i; j < n; ++j) rebound = std::max(rebound, -v[j]);
      m.rebound_speed = rebound;
      break;
    }
  if (std::isnan(m.reversal_time)) m.notes.push_back("the flyer does not reverse within the run");

  if (h.kinetic_energy.size() != n) {
    m.notes.push_back("no flyer_kinetic_energy column: no absorbed energy");
    return m;
  }
  std::vector<double> e = h.kinetic_energy;
  if (h.potential_energy.size() == n) {
    for (size_t i = 0; i < n; ++i) e[i] += h.potential_energy[i];
  } else {
    m.notes.push_back("no flyer_potential_energy column: absorbed energy from the kinetic energy alone");
  }
  m.energy_absorbed = e.front() - e.back();
  if (std::isfinite(m.reversal_time))
    m.energy_absorbed_at_reversal = e.front() - interpolate(Curve{h.time, e}, m.reversal_time);
  return m;
}

}  // namespace latmpm::post
