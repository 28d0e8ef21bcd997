// Metrics of a quasi-static compression curve (load F against plate travel u), with the
// definitions of docs/post.md:
//   start-up transient a run started by setting the platen moving at once rings before the
//                      quasi-static response: a load spike early in the travel (within
//                      `transient_window`) followed by a drop of at least `first_peak_drop`
//                      is the transient, and so is each further spike of its ringing within
//                      the window; it ends at the lowest load after the last. The metrics
//                      below (but the energy) ignore what lies before its end.
//   initial stiffness  least-squares slope of F(u) over the initial range [u_a, u_b]
//                      (ISO 13314:2011 "quasi-elastic gradient", in force units)
//   peak load          the largest F of the series after the transient, its u and t
//   first peak         the first local maximum of the binned curve after the transient
//                      followed by a drop of at least `first_peak_drop` of its value before F
//                      exceeds it again, and not exceeded again within `transient_window`
//                      (that is ringing) (ISO 13314 "first maximum compressive strength")
//   plateau load       mean F over strain [ε_1, ε_2] = [20 %, 30 %] of the gauge length
//                      (ISO 13314 plateau stress × area; 30 % or 40 % by the standard)
//   densification      the maximum of the energy efficiency η(u) = ∫₀ᵘ F du / (F(u) H)
//                      (Tan et al. 2005, J. Mech. Phys. Solids 53;
//                      Li, Magkiriadis & Harrigan 2006, J. Cell. Plast. 42), over points
//                      with F ≥ 10 % of the largest load so far
//   absorbed energy    W = ∫ F du (trapezoid) to the end, and to the densification onset
//   SEA                W / m, m the specimen's mass (real density, not mass-scaled)
//   effective modulus  E* = k H / A: the initial stiffness k times the gauge length H over the
//                      footprint area A (the homogenised Young's modulus of the specimen)
// A curve of two rows (one static increment) has only the stiffness, their secant, and E*.
// Everything SI. A metric that cannot be had is NaN and `notes` says why.
#pragma once
#include <limits>
#include <string>
#include <vector>

namespace latmpm::post {

// One run's load history, SI: s, m, N; equally long, in series order.
struct LoadHistory {
  std::vector<double> time, displacement, load;
};

struct CompressionSettings {
  static constexpr double unset = std::numeric_limits<double>::quiet_NaN();
  // Initial-stiffness fit range [m]; unset: u_a = the end of the start-up transient (0 if
  // none), u_b = half-way from u_a to the first peak, or u_a + 2 % of the gauge length without
  // a first peak (10 % of the travel without a gauge length).
  double fit_from = unset, fit_to = unset;
  double plateau_from_strain = 0.20, plateau_to_strain = 0.30;  // ISO 13314
  double first_peak_drop = 0.05;  // relative drop that makes a local maximum a first peak
  // A spike within this travel is the start-up transient, and a maximum exceeded again within
  // it is ringing [m]; unset: 1 % strain of the gauge length, or 10 % of the travel without a
  // gauge length. 0 switches both off.
  double transient_window = unset;
  // Bin width [m] for the binned curve; unset: 0.1 % strain of the gauge length (ISO 13314's
  // evaluation interval), or 1/500 of the travel without a gauge length.
  double bin = unset;
};

struct CompressionMetrics {
  static constexpr double none = std::numeric_limits<double>::quiet_NaN();
  double transient_end = 0;  // m: travel at which the start-up transient ends (0: none found)
  double stiffness = none, fit_from = none, fit_to = none;  // N/m, m, m
  double effective_modulus = none;                          // Pa
  double peak_load = none, peak_displacement = none, peak_time = none;
  double first_peak_load = none, first_peak_displacement = none;
  double plateau_load = none, plateau_from = none, plateau_to = none;  // N, m, m
  double densification_displacement = none, densification_strain = none, densification_load = none;
  double energy = none, energy_to_densification = none;  // J
  double sea = none, sea_to_densification = none;        // J/kg
  double final_displacement = none;                      // m
  std::vector<std::string> notes;
};

// `gauge_length` (m) turns travel into strain; `mass` (kg) gives SEA; `footprint_area` (m²)
// with the gauge length gives E*. Any may be NaN.
CompressionMetrics compression_metrics(const LoadHistory& history, double gauge_length, double mass,
                                       const CompressionSettings& settings = {},
                                       double footprint_area = std::numeric_limits<double>::quiet_NaN());

// The energy efficiency η·H = ∫₀ᵘ F du / F(u) at each point of a curve ascending in u (m);
// NaN where F ≤ 0. Exposed for tests and plots.
std::vector<double> efficiency_length(const std::vector<double>& u, const std::vector<double>& load);

}  // namespace latmpm::post
