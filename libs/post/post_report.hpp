// latmpm-post's outputs for a set of analysed runs, all in one directory:
//   curves/<run>.load_displacement.csv, curves/<run>.load_time.csv   (mm, N, ms)
//   metrics.csv                                                      (one row per run)
//   checks.csv            (one row per run: energy balance, KE/SE, load ripple; run_checks.hpp)
//   comparison.csv        (with references: each run's errors against each; run_comparison.hpp)
//   plots/<figure>.gp, .png, .svg                                    (gnuplot; the .gp stays)
//   summary.md                                                       (runs, metrics, plots, notes)
// Every file is written under a temporary name and renamed when whole (core/file_transfer),
// and every one says which tool, version, command line and runs made it.
#pragma once
#include <limits>
#include <string>
#include <vector>

#include "post/gnuplot_plot.hpp"
#include "post/run_analysis.hpp"

namespace latmpm::post {

struct ReportContext {
  std::string tool = "latmpm-post";
  std::string version;       // version_string()
  std::string command_line;  // as typed
  std::string created_utc;
  std::string title;         // plot and summary title; "" = a default from the kinds
  double euler_k = clamped_clamped_k;
  std::vector<std::string> references;  // labels of the runs the others are compared with
  double comparison_window = std::numeric_limits<double>::quiet_NaN();  // m; NaN: run_comparison's default
};

struct ReportFiles {
  std::vector<std::string> written;   // paths relative to the output directory
  std::vector<std::string> warnings;  // e.g. "gnuplot not found: no plots"
};

// Writes everything into `out_dir` (created if missing; files of the same names replaced).
ReportFiles write_post_report(const std::string& out_dir, const std::vector<RunAnalysis>& runs,
                              const ReportContext& context, const GnuplotInfo& gnuplot);

// --- pieces, exposed for tests -------------------------------------------------------------

// Legend text: the label, plus "(failed, incomplete)" and the like for runs that did not finish.
std::string legend(const RunAnalysis& run);
// metrics.csv as text (header comments, header "name[unit]", one row per run; empty = n/a).
std::string metrics_csv(const std::vector<RunAnalysis>& runs, const ReportContext& context);
// summary.md as text; `plots` are the figure stems written (with .png), `warnings` listed.
std::string summary_markdown(const std::vector<RunAnalysis>& runs, const ReportContext& context,
                             const std::vector<std::string>& plots, const std::vector<std::string>& warnings);
// "%.*g" of a value, "" for NaN.
std::string number_text(double value, int digits = 6);

}  // namespace latmpm::post
