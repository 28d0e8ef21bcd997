// Writes latmpm-post's output directory: curves, metrics, plots, summary (post_report.hpp).
#include "post/post_report.hpp"

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

#include "core/errors.hpp"
#include "core/file_transfer.hpp"
#include "core/interruption.hpp"
#include "post/report_rows.hpp"
#include "post/run_checks.hpp"
#include "post/run_comparison.hpp"

namespace latmpm::post {

namespace fs = std::filesystem;

namespace {

void write_text(const fs::path& out_dir, const std::string& relative, const std::string& text, ReportFiles& files) {
  write_file_atomically((out_dir / relative).string(), text, "-o");
  files.written.push_back(relative);
}

std::string stem(const RunAnalysis& a) { return file_stem(a.run.label); }

bool mixed_load_columns(const std::vector<RunAnalysis>& runs) {
  std::set<std::string> columns;
  for (const auto& a : runs) columns.insert(a.load_column);
  return columns.size() > 1;
}

// The y label names the load column when all runs share it; otherwise each legend entry does.
std::string load_axis_label(const std::vector<RunAnalysis>& runs) {
  return mixed_load_columns(runs) ? "load (N)" : "load, " + runs.front().load_column + " (N)";
}

std::vector<PlotSpec> figures(const std::vector<RunAnalysis>& runs, const ReportContext& c) {
  const std::string title = c.title.empty() ? "" : c.title + ": ";
  std::vector<std::string> head = provenance_comments(c);
  for (const auto& a : runs) head.push_back(run_comment(a));
  std::vector<PlotSpec> out;

  PlotSpec ld{"load_displacement", title + "load vs plate displacement", "displacement (mm)", load_axis_label(runs), {}, {}, head};
  PlotSpec lt{"load_time", title + "load vs time", "time (ms)", load_axis_label(runs), {}, {}, head};
  PlotSpec fv{"flyer_velocity", title + "flyer velocity vs time", "time (ms)", "flyer velocity (m/s)", {}, {}, head};
  PlotSpec fe{"flyer_energy", title + "flyer energy vs time", "time (ms)", "flyer energy (J)", {}, {}, head};
  std::set<std::string> euler_lines;
  const bool mixed = mixed_load_columns(runs);
  for (const auto& a : runs) {
    if (a.run.series.rows() == 0) continue;
    const bool dashed = !complete(a.run.status);
    const std::string curves = "../curves/" + stem(a);
    const std::string load_legend = legend(a) + (mixed ? " [" + a.load_column + "]" : "");
    if (a.has_travel) ld.series.push_back({curves + ".load_displacement.csv", 1, 2, load_legend, dashed});
    lt.series.push_back({curves + ".load_time.csv", 1, 2, load_legend, dashed});
    const size_t n = a.history.time.size();
    const bool velocity = a.impact_history.velocity.size() == n;
    if (velocity) fv.series.push_back({curves + ".load_time.csv", 1, 3, legend(a), dashed});
    if (a.impact_history.kinetic_energy.size() == n)
      fe.series.push_back({curves + ".load_time.csv", 1, velocity ? 4 : 3, legend(a), dashed});
    if (a.column && std::isfinite(a.column->euler_load)) {
      const auto& f = a.run.specimen;
      const std::string text = "Euler load " + number_text(a.column->euler_load, 4) + " N (t = " +
                               number_text(f.strut_diameter * 1e3, 3) + " mm, L = " + number_text(f.strut_length * 1e3, 3) +
                               " mm, E = " + number_text(f.youngs_modulus / 1e6, 3) + " MPa, K = " +
                               number_text(a.column->k, 3) + ")";
      if (euler_lines.insert(text).second) {
        ld.references.push_back({a.column->euler_load, text});
        lt.references.push_back({a.column->euler_load, text});
      }
    }
  }
  for (PlotSpec* p : {&ld, &lt, &fv, &fe})
    if (!p->series.empty()) out.push_back(*p);
  return out;
}

}  // namespace

ReportFiles write_post_report(const std::string& out_dir_text, const std::vector<RunAnalysis>& runs,
                              const ReportContext& context, const GnuplotInfo& gnuplot) {
  const fs::path out_dir(out_dir_text);
  ReportFiles files;
  std::error_code error;
  for (const char* sub : {"", "curves", "plots"}) {
    fs::create_directories(out_dir / sub, error);
    if (!fs::is_directory(out_dir / sub))
      throw InputError("-o " + out_dir_text, "", "cannot create directory '" + (out_dir / sub).string() + "'");
  }

  // 1. Curves, one pair of files per run.
  for (const auto& a : runs) {
    write_text(out_dir, "curves/" + stem(a) + ".load_time.csv", load_time_csv(a, context), files);
    if (a.has_travel)
      write_text(out_dir, "curves/" + stem(a) + ".load_displacement.csv", load_displacement_csv(a, context), files);
  }
  // 2. Metrics table.
  write_text(out_dir, "metrics.csv", metrics_csv(runs, context), files);
  if (!context.references.empty())
    write_text(out_dir, "comparison.csv", comparison_csv(runs, context.references, provenance_comments(context), context.comparison_window), files);
  write_text(out_dir, "checks.csv", checks_csv(runs, provenance_comments(context)), files);

  // 3. Plots: the script is written first and kept; gnuplot writes temporary names, renamed when done.
  std::vector<std::string> plotted;
  const std::vector<PlotSpec> specs = figures(runs, context);
  if (!gnuplot.available && !specs.empty())
    files.warnings.push_back("gnuplot not found on PATH: no PNG/SVG plots (install gnuplot-nox); the .gp scripts are written");
  for (const PlotSpec& spec : specs) {
    write_text(out_dir, "plots/" + spec.name + ".gp", gnuplot_script(spec, gnuplot.available ? gnuplot.png_terminal : "pngcairo"), files);
    if (!gnuplot.available) continue;
    const std::string tag = ".tmp-" + std::to_string(::getpid());
    const std::string png = spec.name + ".png", svg = spec.name + ".svg";
    const fs::path dir = out_dir / "plots";
    const fs::path png_tmp = dir / (png + tag), svg_tmp = dir / (svg + tag);
    const int png_slot = register_temporary(png_tmp.string());
    const int svg_slot = register_temporary(svg_tmp.string());
    const std::string problem = run_gnuplot(dir.string(), spec.name + ".gp", png + tag, svg + tag);
    // gnuplot can exit 0 after a failed write (a full disk): only complete plots are published.
    const bool complete = problem.empty() && png_is_complete(png_tmp.string()) && svg_is_complete(svg_tmp.string());
    std::error_code rename_error;
    if (complete) {
      fs::rename(png_tmp, dir / png, rename_error);
      if (!rename_error) fs::rename(svg_tmp, dir / svg, rename_error);
    }
    if (!complete || rename_error) {
      fs::remove(png_tmp, error);
      fs::remove(svg_tmp, error);
    }
    unregister_temporary(png_slot);
    unregister_temporary(svg_slot);
    if (rename_error) throw OutputError((dir / png).string(), "cannot rename the plot into place: " + rename_error.message());
    if (complete) {
      files.written.push_back("plots/" + png);
      files.written.push_back("plots/" + svg);
      plotted.push_back(spec.name);
    } else if (problem.empty()) {
      // gnuplot reported nothing but left a file cut short: the disk is full, not the plot wrong.
      throw OutputError((dir / png).string(), "gnuplot could not finish the plot (disk full?)");
    } else {
      files.warnings.push_back("gnuplot failed on plots/" + spec.name + ".gp: " + problem.substr(0, problem.find('\n')));
    }
  }

  // 4. The summary, last: it lists what the steps above wrote and what went wrong.
  write_text(out_dir, "summary.md", summary_markdown(runs, context, plotted, files.warnings), files);
  return files;
}

}  // namespace latmpm::post
