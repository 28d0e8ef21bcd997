#include "core/units.hpp"
#include "post/compression_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "post/curve.hpp"

namespace latmpm::post {

namespace {

std::string mm(double metres) { return format_millimetres(metres, 3); }

// The first local maximum after index `from` followed by a relative drop of at least `drop`
// before the curve climbs above it again, and not climbed above again within `persist` of
// travel (ringing, not a failing structure); returns the index or -1.
long first_peak(const Curve& c, double drop, size_t from = 0, double persist = 0) {
  for (size_t k = from + 1; k + 1 < c.size(); ++k) {
    if (!(c.y[k] >= c.y[k - 1] && c.y[k] > c.y[k + 1]) || c.y[k] <= 0) continue;
    double lowest = c.y[k];
    size_t j = k + 1;
    for (; j < c.size() && c.y[j] <= c.y[k]; ++j) lowest = std::min(lowest, c.y[j]);
    if (lowest > (1 - drop) * c.y[k]) continue;
    if (j < c.size() && c.x[j] - c.x[k] <= persist) continue;
    return long(k);
  }
  return -1;
}

// The start-up transient on the binned curve: a first peak within `window` of the start is
// a spike of the platen set moving at once (the quasi-static response cannot peak that
// early); it ends at the lowest load after the spike, searched until the curve climbs above
// the spike again or two windows on. The ringing repeats: spike after spike within the window
// belongs to the transient. Returns the index where it ends, or 0 when there is no spike.
size_t transient_end(const Curve& c, double drop, double window) {
  if (!(window > 0)) return 0;
  size_t settled = 0;
  for (;;) {
    const long spike = first_peak(c, drop, settled);
    if (spike < 0 || c.x[size_t(spike)] - c.x.front() > window) return settled;
    const size_t k = size_t(spike);
    size_t lowest = k;
    for (size_t j = k + 1; j < c.size() && c.y[j] <= c.y[k] && c.x[j] - c.x.front() <= 2 * window; ++j)
      if (c.y[j] < c.y[lowest]) lowest = j;
    if (lowest == k) return settled;
    settled = lowest;
  }
}

}  // namespace

std::vector<double> efficiency_length(const std::vector<double>& u, const std::vector<double>& load) {
  const std::vector<double> work = cumulative_trapezoid(Curve{u, load});
  std::vector<double> eta(u.size(), std::nan(""));
  for (size_t i = 0; i < u.size(); ++i)
    if (load[i] > 0) eta[i] = work[i] / load[i];
  return eta;
}

CompressionMetrics compression_metrics(const LoadHistory& h, double gauge, double mass,
                                       const CompressionSettings& s, double footprint_area) {
  CompressionMetrics m;
  const Curve raw{h.displacement, h.load};
  const Curve curve = monotone_prefix(raw);
  const bool have_gauge = std::isfinite(gauge) && gauge > 0;
  // E* = k H / A, once the stiffness is known.
  auto set_stiffness = [&](double from, double to) {
    m.fit_from = from, m.fit_to = to;
    m.stiffness = fitted_slope(curve, from, to);
    if (std::isnan(m.stiffness))
      m.notes.push_back("initial stiffness: fewer than two rows in the fit range " + mm(from) + " to " + mm(to));
    else if (!have_gauge || !(footprint_area > 0))
      m.notes.push_back("effective modulus: no gauge length or footprint_area in the point files' parameters");
    else
      m.effective_modulus = m.stiffness * gauge / footprint_area;
  };
  if (curve.size() < 2 || !(curve.x.back() > curve.x.front())) {
    m.notes.push_back("fewer than two rows of increasing travel: no compression metrics");
    return m;
  }
  if (curve.size() < raw.size())
    m.notes.push_back("the travel goes back after " + mm(curve.x.back()) + ": metrics use the curve up to there");
  const double travel = curve.x.back();
  m.final_displacement = travel;
  if (curve.size() == 2) {  // one static increment: its secant is the stiffness, nothing else is
    m.notes.push_back("two rows of travel: only the initial stiffness (their secant) and the effective modulus");
    set_stiffness(std::isfinite(s.fit_from) ? s.fit_from : curve.x.front(), std::isfinite(s.fit_to) ? s.fit_to : travel);
    return m;
  }

  // The binned curve: solver oscillation averaged out, evenly spaced in u.
  double bin = s.bin;
  if (!(bin > 0)) bin = have_gauge ? 1e-3 * gauge : travel / 500;
  bin = std::min(bin, (travel - curve.x.front()) / 10);
  const Curve binned = bin_average(curve, curve.x.front(), travel, bin);

  // The start-up transient, excluded from everything but the energy.
  const double window = std::isfinite(s.transient_window) ? s.transient_window
                        : have_gauge                      ? 0.01 * gauge
                                                          : 0.1 * travel;
  const size_t settled = transient_end(binned, s.first_peak_drop, window);
  if (settled > 0) {
    m.transient_end = binned.x[settled];
    m.notes.push_back("start-up transient: a load spike before " + mm(m.transient_end) +
                      " is left out of the peaks, the stiffness fit and the densification onset");
  }

  // Peak load over the series rows as written, after the transient.
  size_t peak = 0;
  for (size_t i = 0; i < curve.size(); ++i)
    if (curve.x[i] >= m.transient_end && (curve.x[peak] < m.transient_end || curve.y[i] > curve.y[peak])) peak = i;
  m.peak_load = curve.y[peak];
  m.peak_displacement = curve.x[peak];
  for (size_t i = 0; i < h.displacement.size(); ++i)
    if (h.displacement[i] == curve.x[peak] && h.load[i] == curve.y[peak]) {
      m.peak_time = h.time[i];
      break;
    }

  const long fp = first_peak(binned, s.first_peak_drop, settled, window);
  if (fp >= 0) {
    m.first_peak_load = binned.y[size_t(fp)];
    m.first_peak_displacement = binned.x[size_t(fp)];
  } else {
    m.notes.push_back("no first peak: the load never drops by " + std::to_string(int(s.first_peak_drop * 100)) +
                      " % after a maximum");
  }

  // Initial stiffness: linear least squares over the initial range.
  const double fit_from = std::isfinite(s.fit_from) ? s.fit_from : settled > 0 ? m.transient_end : curve.x.front();
  set_stiffness(fit_from, std::isfinite(s.fit_to) ? s.fit_to
                          : fp >= 0              ? 0.5 * (fit_from + m.first_peak_displacement)
                          : have_gauge           ? std::min(fit_from + 0.02 * gauge, travel)
                                                 : fit_from + 0.1 * travel);

  // Plateau (ISO 13314): mean load between two strains.
  if (!have_gauge) {
    m.notes.push_back("plateau load: no gauge length (lattice_zmin/zmax) to turn travel into strain");
  } else {
    m.plateau_from = s.plateau_from_strain * gauge;
    m.plateau_to = s.plateau_to_strain * gauge;
    if (travel >= m.plateau_to) {
      m.plateau_load = interval_mean(curve, m.plateau_from, m.plateau_to);
    } else {
      char text[160];
      std::snprintf(text, sizeof text, "plateau load: the run ends at %.3g %% strain, before %.3g %%",
                    100 * travel / gauge, 100 * s.plateau_to_strain);
      m.notes.push_back(text);
    }
  }

  // Densification onset: maximum of the energy efficiency on the binned curve, over points
  // whose load is at least 10 % of the largest load so far (deep troughs after a collapse
  // make W/F spike without meaning).
  // The work counts from the end of the transient: the spike's work over the low load
  // after it would make W/F peak there.
  const std::vector<double> settled_x(binned.x.begin() + long(settled), binned.x.end());
  std::vector<double> eta(settled, std::nan(""));
  const std::vector<double> settled_eta =
      efficiency_length(settled_x, std::vector<double>(binned.y.begin() + long(settled), binned.y.end()));
  eta.insert(eta.end(), settled_eta.begin(), settled_eta.end());
  long best = -1;
  double highest = 0;
  for (size_t i = settled; i < eta.size(); ++i) {
    highest = std::max(highest, binned.y[i]);
    if (std::isfinite(eta[i]) && binned.y[i] >= 0.1 * highest && (best < 0 || eta[i] > eta[size_t(best)]))
      best = long(i);
  }
  // A maximum within the last transient window is the end of the run, not an onset.
  if (best < 0 || size_t(best) + 1 >= eta.size() || binned.x.back() - binned.x[size_t(best)] < window) {
    m.notes.push_back("densification onset: not reached (the energy efficiency still rises at the end of the run)");
  } else {
    m.densification_displacement = binned.x[size_t(best)];
    m.densification_load = binned.y[size_t(best)];
    if (have_gauge) m.densification_strain = m.densification_displacement / gauge;
  }

  // Absorbed energy: work done on the specimen, ∫ F du.
  const std::vector<double> work = cumulative_trapezoid(curve);
  m.energy = work.back();
  if (std::isfinite(m.densification_displacement))
    m.energy_to_densification = interpolate(Curve{curve.x, work}, m.densification_displacement);
  if (std::isfinite(mass) && mass > 0) {
    m.sea = m.energy / mass;
    m.sea_to_densification = m.energy_to_densification / mass;
  } else {
    m.notes.push_back("SEA: specimen mass unknown");
  }
  return m;
}

}  // namespace latmpm::post
