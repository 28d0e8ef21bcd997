// CSV outputs of latmpm-post: metrics.csv, and the text helpers the other outputs share.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "post/post_report.hpp"
#include "post/report_rows.hpp"

namespace latmpm::post {

std::string number_text(double value, int digits) {
  if (!std::isfinite(value)) return "";
  char text[64];
  std::snprintf(text, sizeof text, "%.*g", digits, value);
  return text;
}

std::string legend(const RunAnalysis& a) {
  switch (a.run.status) {
    case RunStatus::finished: return a.run.label;
    case RunStatus::max_steps: return a.run.label + " (stopped at max_steps, incomplete)";
    case RunStatus::failed: return a.run.label + " (failed, incomplete)";
    case RunStatus::unfinished: return a.run.label + " (unfinished, incomplete)";
  }
  return a.run.label;
}

std::string csv_cell(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::vector<std::string> provenance_comments(const ReportContext& c) {
  return {"made by " + c.tool + " " + c.version + " at " + c.created_utc, "command: " + c.command_line};
}

std::string run_comment(const RunAnalysis& a) {
  return "run '" + a.run.label + "': " + std::filesystem::absolute(a.run.path).lexically_normal().string() + " (" +
         to_string(a.run.status) + "), load column " + a.load_column;
}

std::vector<MetricCell> metric_cells(const RunAnalysis& a) {
  constexpr double mm = 1e3, ms = 1e3;
  const auto& f = a.run.specimen;
  const auto& h = a.history;
  std::vector<MetricCell> cells = {
      {"label", "", a.run.label, false},
      {"run_dir", "", a.run.path, false},
      {"status", "", to_string(a.run.status), false},
      {"kind", "", to_string(a.kind), false},
      {"load_column", "", a.load_column, false},
      {"rows", "1", std::to_string(a.run.series.rows()), true},
      {"end_time", "ms", number_text(h.time.empty() ? NAN : h.time.back() * ms), true},
      {"travel", "mm", number_text(h.displacement.empty() ? NAN : h.displacement.back() * mm), true},
      {"specimen_mass", "g", number_text(f.mass * 1e3), true},
  };
  auto add = [&](const char* name, const char* unit, double v) { cells.push_back({name, unit, number_text(v), true}); };
  const CompressionMetrics c = a.compression.value_or(CompressionMetrics{});
  add("initial_stiffness", "N/mm", c.stiffness / mm);
  add("stiffness_fit_from", "mm", c.fit_from * mm);
  add("stiffness_fit_to", "mm", c.fit_to * mm);
  add("effective_modulus", "MPa", c.effective_modulus * 1e-6);
  add("peak_load", "N", c.peak_load);
  add("peak_displacement", "mm", c.peak_displacement * mm);
  add("peak_time", "ms", c.peak_time * ms);
  add("first_peak_load", "N", c.first_peak_load);
  add("first_peak_displacement", "mm", c.first_peak_displacement * mm);
  add("plateau_load", "N", c.plateau_load);
  add("plateau_from", "mm", c.plateau_from * mm);
  add("plateau_to", "mm", c.plateau_to * mm);
  add("densification_displacement", "mm", c.densification_displacement * mm);
  add("densification_strain", "1", c.densification_strain);
  add("densification_load", "N", c.densification_load);
  add("absorbed_energy", "J", c.energy);
  add("absorbed_energy_to_densification", "J", c.energy_to_densification);
  add("sea", "J/kg", c.sea);
  add("sea_to_densification", "J/kg", c.sea_to_densification);
  const ColumnMetrics col = a.column.value_or(ColumnMetrics{});
  add("euler_k", "1", col.k);
  add("euler_load", "N", col.euler_load);
  add("peak_to_euler", "1", col.peak_ratio);
  add("post_buckling_load", "N", col.post_buckling_load);
  add("post_buckling_to_euler", "1", col.post_buckling_ratio);
  const ImpactMetrics i = a.impact.value_or(ImpactMetrics{});
  add("impact_speed", "m/s", i.impact_speed);
  add("impact_peak_load", "N", i.peak_load);
  add("impact_peak_time", "ms", i.peak_time * ms);
  add("reversal_time", "ms", i.reversal_time * ms);
  add("rebound_speed", "m/s", i.rebound_speed);
  add("flyer_energy_absorbed", "J", i.energy_absorbed);
  add("flyer_energy_absorbed_at_reversal", "J", i.energy_absorbed_at_reversal);
  return cells;
}

std::string metrics_csv(const std::vector<RunAnalysis>& runs, const ReportContext& context) {
  std::ostringstream out;
  for (const auto& line : provenance_comments(context)) out << "# " << one_line(line) << "\n";
  for (const auto& a : runs) out << "# " << one_line(run_comment(a)) << "\n";
  out << "# definitions: docs/post.md; empty cell = not applicable or not found (summary.md says why)\n";
  if (runs.empty()) return out.str();
  const std::vector<MetricCell> head = metric_cells(runs.front());
  for (size_t i = 0; i < head.size(); ++i)
    out << (i ? "," : "") << head[i].name << (head[i].unit.empty() ? "" : "[" + head[i].unit + "]");
  out << "\n";
  for (const auto& a : runs) {
    const std::vector<MetricCell> cells = metric_cells(a);
    for (size_t i = 0; i < cells.size(); ++i) out << (i ? "," : "") << csv_cell(cells[i].value);
    out << "\n";
  }
  return out.str();
}

std::string load_displacement_csv(const RunAnalysis& a, const ReportContext& context) {
  std::ostringstream out;
  for (const auto& line : provenance_comments(context)) out << "# " << one_line(line) << "\n";
  out << "# " << one_line(run_comment(a)) << "\n";
  out << "displacement[mm]," << a.load_column << "[N]\n";
  for (size_t i = 0; i < a.history.time.size(); ++i)
    out << number_text(a.history.displacement[i] * 1e3, 10) << "," << number_text(a.history.load[i], 10) << "\n";
  return out.str();
}

std::string load_time_csv(const RunAnalysis& a, const ReportContext& context) {
  const ImpactHistory& f = a.impact_history;
  const size_t n = a.history.time.size();
  const bool velocity = f.velocity.size() == n && n > 0, energy = f.kinetic_energy.size() == n && n > 0;
  const bool potential = f.potential_energy.size() == n;
  std::ostringstream out;
  for (const auto& line : provenance_comments(context)) out << "# " << one_line(line) << "\n";
  out << "# " << one_line(run_comment(a)) << "\n";
  out << "time[ms]," << a.load_column << "[N]";
  if (velocity) out << ",flyer_velocity[m/s]";
  if (energy) out << (potential ? ",flyer_energy[J]" : ",flyer_kinetic_energy[J]");
  out << "\n";
  for (size_t i = 0; i < n; ++i) {
    out << number_text(a.history.time[i] * 1e3, 10) << "," << number_text(a.history.load[i], 10);
    if (velocity) out << "," << number_text(f.velocity[i], 10);
    if (energy) out << "," << number_text(f.kinetic_energy[i] + (potential ? f.potential_energy[i] : 0.0), 10);
    out << "\n";
  }
  return out.str();
}

}  // namespace latmpm::post
