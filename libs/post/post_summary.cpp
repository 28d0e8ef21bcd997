// summary.md: what was read, how each run ended, the metrics of each kind, the plots and
// every note about what could not be computed. Definitions are in docs/post.md.
#include <cmath>
#include <sstream>

#include "post/post_report.hpp"
#include "post/report_rows.hpp"

namespace latmpm::post {

namespace {

std::string cell(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out.empty() ? "–" : out;
}

std::string num(double value, int digits = 4) { return cell(number_text(value, digits)); }

// "12.3 at 4.5" when both are known.
std::string at(double value, double where, int digits = 4) {
  if (!std::isfinite(value)) return "–";
  return number_text(value, digits) + (std::isfinite(where) ? " at " + number_text(where, 3) : "");
}

void compression_table(std::ostream& md, const std::vector<const RunAnalysis*>& runs) {
  md << "## Compression\n\n"
     << "| run | initial stiffness (N/mm) | fit range (mm) | E* (MPa) | peak load (N) at u (mm) | first peak (N) at u (mm) "
        "| plateau load (N) | plateau range (mm) | densification onset u (mm) | onset strain | absorbed energy (J) "
        "| to onset (J) | SEA (J/kg) | SEA to onset (J/kg) |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const RunAnalysis* a : runs) {
    const CompressionMetrics& c = *a->compression;
    md << "| " << cell(legend(*a)) << " | " << num(c.stiffness / 1e3) << " | " << number_text(c.fit_from * 1e3, 3)
       << "–" << number_text(c.fit_to * 1e3, 3) << " | " << num(c.effective_modulus / 1e6) << " | " << at(c.peak_load, c.peak_displacement * 1e3) << " | "
       << at(c.first_peak_load, c.first_peak_displacement * 1e3) << " | " << num(c.plateau_load) << " | "
       << (std::isfinite(c.plateau_from) ? number_text(c.plateau_from * 1e3, 3) + "–" + number_text(c.plateau_to * 1e3, 3)
                                         : "–")
       << " | " << num(c.densification_displacement * 1e3) << " | " << num(c.densification_strain, 3) << " | "
       << num(c.energy) << " | " << num(c.energy_to_densification) << " | " << num(c.sea) << " | "
       << num(c.sea_to_densification) << " |\n";
  }
  md << "\n";
}

void column_table(std::ostream& md, const std::vector<const RunAnalysis*>& runs) {
  md << "## Column buckling\n\n"
     << "Euler load P = π² E I / (K L)², I = π t⁴ / 64 (paper A Sec. 4); post-buckling load = mean load "
        "over the last quarter of the travel.\n\n"
     << "| run | t (mm) | L (mm) | E (MPa) | K | Euler load (N) | peak load (N) at u (mm) | peak / Euler "
        "| post-buckling load (N) | post-buckling / Euler | initial stiffness (N/mm) |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const RunAnalysis* a : runs) {
    const ColumnMetrics& c = *a->column;
    const SpecimenFacts& f = a->run.specimen;
    const CompressionMetrics& m = *a->compression;
    md << "| " << cell(legend(*a)) << " | " << num(f.strut_diameter * 1e3) << " | " << num(f.strut_length * 1e3) << " | "
       << num(f.youngs_modulus / 1e6) << " | " << num(c.k) << " | " << num(c.euler_load) << " | "
       << at(m.peak_load, m.peak_displacement * 1e3) << " | " << num(c.peak_ratio, 3) << " | "
       << num(c.post_buckling_load) << " | " << num(c.post_buckling_ratio, 3) << " | " << num(m.stiffness / 1e3)
       << " |\n";
  }
  md << "\n";
}

void impact_table(std::ostream& md, const std::vector<const RunAnalysis*>& runs) {
  md << "## Impact\n\n"
     << "| run | impact speed (m/s) | peak load (N) | at (ms) | reversal time (ms) | rebound speed (m/s) "
        "| flyer energy absorbed (J) | absorbed at reversal (J) |\n"
     << "|---|---|---|---|---|---|---|---|\n";
  for (const RunAnalysis* a : runs) {
    const ImpactMetrics& i = *a->impact;
    md << "| " << cell(legend(*a)) << " | " << num(i.impact_speed) << " | " << num(i.peak_load) << " | "
       << num(i.peak_time * 1e3) << " | " << num(i.reversal_time * 1e3) << " | " << num(i.rebound_speed) << " | "
       << num(i.energy_absorbed) << " | " << num(i.energy_absorbed_at_reversal) << " |\n";
  }
  md << "\n";
}

}  // namespace

std::string summary_markdown(const std::vector<RunAnalysis>& runs, const ReportContext& context,
                             const std::vector<std::string>& plots, const std::vector<std::string>& warnings) {
  std::ostringstream md;
  md << "# " << (context.title.empty() ? "latmpm-post summary" : context.title) << "\n\n"
     << "Made by " << context.tool << " " << context.version << " at " << context.created_utc << ":\n\n"
     << "```sh\n" << context.command_line << "\n```\n\n"
     << "Definitions of every metric: docs/post.md. Tables: `metrics.csv` (all metrics, one row per run); "
        "curves: `curves/` (mm, N, ms).\n\n";

  md << "## Runs\n\n"
     << "| run | directory | status | kind | load column | rows | end time (ms) | travel (mm) | specimen mass (g) |\n"
     << "|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& a : runs) {
    const auto& h = a.history;
    md << "| " << cell(a.run.label) << " | `" << a.run.path << "` | " << (complete(a.run.status) ? "" : "**")
       << to_string(a.run.status) << (complete(a.run.status) ? "" : "**") << " | " << to_string(a.kind) << " | "
       << a.load_column << " | " << a.run.series.rows() << " | " << num(h.time.empty() ? NAN : h.time.back() * 1e3)
       << " | " << num(h.displacement.empty() ? NAN : h.displacement.back() * 1e3) << " | "
       << num(a.run.specimen.mass * 1e3) << " |\n";
  }
  md << "\n";

  std::vector<const RunAnalysis*> incomplete, compression, column, impact;
  for (const auto& a : runs) {
    if (!complete(a.run.status)) incomplete.push_back(&a);
    if (a.column) column.push_back(&a);
    else if (a.compression) compression.push_back(&a);
    if (a.impact) impact.push_back(&a);
  }
  if (!incomplete.empty()) {
    md << "### Runs that did not finish\n\n"
       << "Their curves are plotted dashed and marked incomplete; their metrics cover only the part that ran.\n\n";
    for (const RunAnalysis* a : incomplete) {
      md << "- **" << a->run.label << "** (`" << a->run.path << "`): " << to_string(a->run.status) << " — `"
         << a->run.status_line << "`";
      if (!a->run.stop_reason.empty()) md << "; `" << a->run.stop_reason << "`";
      md << "\n";
    }
    md << "\n";
  }

  if (!compression.empty()) compression_table(md, compression);
  if (!column.empty()) column_table(md, column);
  if (!impact.empty()) impact_table(md, impact);

  if (!plots.empty()) {
    md << "## Plots\n\n";
    for (const auto& p : plots)
      md << "![" << p << "](plots/" << p << ".png)\n\n[" << p << ".svg](plots/" << p << ".svg), script [" << p
         << ".gp](plots/" << p << ".gp)\n\n";
  }

  bool any_notes = !warnings.empty();
  for (const auto& a : runs) any_notes = any_notes || !a.notes.empty();
  if (any_notes) {
    md << "## Notes\n\n";
    for (const auto& w : warnings) md << "- " << w << "\n";
    for (const auto& a : runs)
      for (const auto& n : a.notes) md << "- " << a.run.label << ": " << n << "\n";
    md << "\n";
  }
  return md.str();
}

}  // namespace latmpm::post
