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

}  // namespace

RunComparison compare_runs(const RunAnalysis& reference, const RunAnalysis& run) {
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
  return c;
}

std::string comparison_csv(const std::vector<RunAnalysis>& runs, const std::vector<std::string>& references,
                           const std::vector<std::string>& provenance_comments) {
  std::ostringstream out;
  for (const auto& line : provenance_comments) out << "# " << line << "\n";
  out << "# errors of each run against a reference run (docs/post.md, \"Comparing runs\")\n";
  out << "reference,label,curve_error[1],peak_error[1],late_error[1],euler_error[1],ke_over_se[1]\n";
  for (const std::string& label : references) {
    const auto ref = std::find_if(runs.begin(), runs.end(), [&](const RunAnalysis& a) { return a.run.label == label; });
    if (ref == runs.end()) throw InputError("--reference", label, "not the label of one of the runs");
    for (const RunAnalysis& a : runs) {
      const RunComparison c = compare_runs(*ref, a);
      out << label << "," << a.run.label << "," << number_text(c.curve_error) << "," << number_text(c.peak_error) << ","
          << number_text(c.late_error) << "," << number_text(c.euler_error) << "," << number_text(c.ke_over_se) << "\n";
    }
  }
  return out.str();
}

}  // namespace latmpm::post
