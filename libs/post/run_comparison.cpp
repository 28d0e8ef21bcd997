#include "post/run_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/errors.hpp"
#include "post/curve.hpp"
#include "post/post_report.hpp"
#include "post/run_checks.hpp"

namespace latmpm::post {

namespace {

double peak(const std::vector<double>& load) {
  return load.empty() ? RunComparison::none : *std::max_element(load.begin(), load.end());
}

// The mean load of the rows within [centre - half, centre + half] of travel (NaN: none).
double window_mean(const LoadHistory& h, double centre, double half) {
  double sum = 0;
  size_t n = 0;
  for (size_t i = 0; i < h.displacement.size(); ++i)
    if (h.displacement[i] >= centre - half && h.displacement[i] <= centre + half) sum += h.load[i], ++n;
  return n > 0 ? sum / double(n) : RunComparison::none;
}

void window_load_error(const RunAnalysis& reference, const RunAnalysis& run, double window, RunComparison& c) {
  const auto& d = reference.history.displacement;
  if (!reference.has_travel || !run.has_travel) return;
  const double end = d.back();
  if (!(end > 0)) return;
  if (!(window > 0)) window = end / 8;
  std::vector<double> ref_means, run_means, stations;
  for (long k = 1; k <= long(end / window + 1e-9); ++k) {
    stations.push_back(window * double(k));
    ref_means.push_back(window_mean(reference.history, stations.back(), window / 2));
    run_means.push_back(window_mean(run.history, stations.back(), window / 2));
  }
  if (stations.empty()) return;
  double highest = 0;  // over the stations whose window holds reference rows (others are NaN)
  for (double m : ref_means)
    if (std::isfinite(m)) highest = std::max(highest, m);
  if (!(highest > 0)) return;
  for (size_t k = 0; k < stations.size(); ++k) {
    const double error = std::abs(run_means[k] - ref_means[k]) / highest;
    if (std::isfinite(error) && (std::isnan(c.window_load_error) || error > c.window_load_error))
      c.window_load_error = error, c.window_load_error_at = stations[k];
  }
}

}  // namespace

RunComparison compare_runs(const RunAnalysis& reference, const RunAnalysis& run, double window) {
  RunComparison c;
  const Curve ref{reference.history.displacement, reference.history.load};
  const Curve cur{run.history.displacement, run.history.load};
  if (reference.has_travel && run.has_travel && ref.x.back() > 0) {
    // Both curves averaged over the same bins of the reference's travel.
    const double travel = ref.x.back(), step = travel / comparison_bins;
    const Curve a = bin_average(monotone_prefix(ref), 0, travel, step);
    const Curve b = bin_average(monotone_prefix(cur), 0, travel, step);
    double difference = 0, norm = 0;
    for (size_t k = 0; k < a.size() && k < b.size(); ++k) {
      difference += (b.y[k] - a.y[k]) * (b.y[k] - a.y[k]);
      norm += a.y[k] * a.y[k];
    }
    if (norm > 0) c.curve_error = std::sqrt(difference / norm);
  }
  c.peak_error = peak(run.history.load) / peak(reference.history.load) - 1;
  if (run.column && reference.column) {
    c.late_error = run.column->post_buckling_load / reference.column->post_buckling_load - 1;
    c.euler_error = run.column->post_buckling_ratio - 1;
  } else if (reference.has_travel && run.has_travel) {
    c.late_error = trapezoid(cur) / trapezoid(ref) - 1;
  }
  c.ke_over_se = kinetic_over_strain(run);
  if (!run.history.load.empty() && !reference.history.load.empty())
    c.final_error = run.history.load.back() / reference.history.load.back() - 1;
  window_load_error(reference, run, window, c);
  return c;
}

std::string comparison_csv(const std::vector<RunAnalysis>& runs, const std::vector<std::string>& references,
                           const std::vector<std::string>& provenance_comments, double window) {
  std::ostringstream out;
  for (const auto& line : provenance_comments) out << "# " << line << "\n";
  out << "# errors of each run against a reference run (docs/post.md, \"Comparing runs\")\n";
  out << "reference,label,curve_error[1],peak_error[1],late_error[1],euler_error[1],ke_over_se[1],final_error[1],window_load_error[1],window_load_error_at[mm]\n";
  for (const std::string& label : references) {
    const auto ref = std::find_if(runs.begin(), runs.end(), [&](const RunAnalysis& a) { return a.run.label == label; });
    if (ref == runs.end()) throw InputError("--reference", label, "not the label of one of the runs");
    for (const RunAnalysis& a : runs) {
      const RunComparison c = compare_runs(*ref, a, window);
      out << label << "," << a.run.label << "," << number_text(c.curve_error) << "," << number_text(c.peak_error) << ","
          << number_text(c.late_error) << "," << number_text(c.euler_error) << "," << number_text(c.ke_over_se) << ","
          << number_text(c.final_error) << "," << number_text(c.window_load_error) << ","
          << number_text(c.window_load_error_at * 1e3) << "\n";
    }
  }
  return out.str();
}

}  // namespace latmpm::post
