// How far one run lies from a reference run of the same test: the errors of the speed
// against accuracy study (make tradeoff, docs/tradeoff.md; latmpm-post --reference). All from
// the runs' load histories (the analysis' load column) and series:
//   curve_error  relative L2 difference of the load-displacement curves, both averaged over
//                50 bins of the reference's travel (removes the explicit solver's step-to-step
//                ripple): sqrt(sum (F_run - F_ref)^2 / sum F_ref^2) over the bins
//   peak_error   (peak load of the run - the reference's) / the reference's
//   late_error   column: post-buckling load (ColumnMetrics) against the reference's;
//                otherwise the work W = int F du (trapezoid rule) against the reference's
//   euler_error  column: post-buckling load / Euler load - 1 (ColumnMetrics); NaN otherwise
//   ke_over_se   the largest kinetic / strain energy ratio over the second half of the run's
//                travel: small when the run is quasi-static (run_checks.hpp; NaN without them)
//   final_error  the load of the run's last row over the reference's, - 1 (a failed run's
//                last row is where it stopped)
//   window_load_error, window_load_error_at  issue 14's load error: at every `window` of the
//                reference's travel (stations w, 2w, ... up to its end) the mean load over the
//                rows within ±w/2 of the station, for both runs; the largest difference as a
//                fraction of the reference's largest such mean, and the station where it is (m)
#pragma once
#include <limits>
#include <string>
#include <vector>

#include "post/run_analysis.hpp"

namespace latmpm::post {

struct RunComparison {
  static constexpr double none = std::numeric_limits<double>::quiet_NaN();
  double curve_error = none, peak_error = none, late_error = none, euler_error = none, ke_over_se = none;
  double final_error = none;
  double window_load_error = none, window_load_error_at = none;
};

inline constexpr int comparison_bins = 50;

// `window` (m) of the windowed load error; NaN: 1/8 of the reference's travel.
RunComparison compare_runs(const RunAnalysis& reference, const RunAnalysis& run,
                           double window = std::numeric_limits<double>::quiet_NaN());

// comparison.csv: one row per (reference, run) pair, references in the order given (labels of
// `runs`); InputError("--reference", label, ...) for a label that is not one of the runs.
std::string comparison_csv(const std::vector<RunAnalysis>& runs, const std::vector<std::string>& references,
                           const std::vector<std::string>& provenance_comments,
                           double window = std::numeric_limits<double>::quiet_NaN());

}  // namespace latmpm::post
