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
#pragma once
#include <limits>
#include <string>
#include <vector>

#include "post/run_analysis.hpp"

namespace latmpm::post {

struct RunComparison {
  static constexpr double none = std::numeric_limits<double>::quiet_NaN();
  double curve_error = none, peak_error = none, late_error = none, euler_error = none, ke_over_se = none;
};

inline constexpr int comparison_bins = 50;

RunComparison compare_runs(const RunAnalysis& reference, const RunAnalysis& run);

// comparison.csv: one row per (reference, run) pair, references in the order given (labels of
// `runs`); InputError("--reference", label, ...) for a label that is not one of the runs.
std::string comparison_csv(const std::vector<RunAnalysis>& runs, const std::vector<std::string>& references,
                           const std::vector<std::string>& provenance_comments);

}  // namespace latmpm::post
