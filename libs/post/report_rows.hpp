// Internal to libs/post's report writers: the shared pieces of metrics.csv, the curve CSVs
// and summary.md, so the three agree on names, units and formatting.
#pragma once
#include <string>
#include <vector>

#include "post/post_report.hpp"

namespace latmpm::post {

struct MetricCell {
  std::string name, unit, value;  // value already formatted, "" = n/a
  bool numeric = true;
};

// Every metric of a run, in metrics.csv's column order, in table units (mm, ms, N, J, g).
std::vector<MetricCell> metric_cells(const RunAnalysis& run);
// Provenance lines (written after "# "): tool, version, time, command line.
std::vector<std::string> provenance_comments(const ReportContext& context);
// One run: label, absolute directory, status, load column.
std::string run_comment(const RunAnalysis& run);
std::string csv_cell(const std::string& text);
std::string load_displacement_csv(const RunAnalysis& run, const ReportContext& context);
std::string load_time_csv(const RunAnalysis& run, const ReportContext& context);

}  // namespace latmpm::post
