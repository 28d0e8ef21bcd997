// latmpm-post: load curves, metrics, plots and a summary from latmpm-solve run directories.
// Thin: reading runs, metrics and the report live in libs/post.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "core/command_line.hpp"
#include "core/errors.hpp"
#include "core/provenance.hpp"
#include "core/tool_main.hpp"
#include "post/post_report.hpp"
#include "post/run_analysis.hpp"
#include "post/run_directory.hpp"

namespace {

const char* const manual =
    R"(latmpm-post: load curves, metrics, plots and a summary from latmpm-solve runs.

Reads one or more run directories (latmpm-solve -o RUN_DIR) and writes into OUT_DIR:
curves/<run>.load_displacement.csv and .load_time.csv (mm, N, ms), metrics.csv (one row per
run), plots/*.png, *.svg and the gnuplot script *.gp beside them (all runs overlaid), and
summary.md; with --reference LABEL (repeatable) also comparison.csv: every run's errors
against that run (curve, peak, late load or work, Euler; KE/SE). Metrics by kind of test (docs/post.md has the exact definitions):
  compression  initial stiffness, peak and first peak load, plateau load (ISO 13314,
               20-30 % strain), densification onset (energy-efficiency maximum), absorbed
               energy and specific energy absorption (per specimen mass)
  column       Euler load pi^2 E I / (K L)^2 from the point file's diameter and length, the
               peak and post-buckling loads and their ratios to it (K = 0.5: clamped-clamped)
  impact       peak load, time to reversal, rebound speed, flyer energy absorbed (needs the
               series columns flyer_velocity, flyer_kinetic_energy, flyer_potential_energy)
Runs that failed or did not finish are named in the summary and plotted dashed as
"incomplete". Exit status: 0 done (also with failed runs: see summary.md), 1 usage, 2 a
directory that is not a run, or bad options (one line naming it).

Sample runs (a coarse 16 mm column with uGIMP, again with quadratic B-splines, and a third run
stopped early by max_steps, which the summary marks incomplete):
  $ latmpm-lattice --column --diameter 1.6mm --length 16mm --end-plates 0.8mm -o c.h5
  $ latmpm-voxelize c.h5 --cell 0.8mm --ppc 2 -o c-points.h5
  $ latmpm-solve $LATMPM_SOURCE_DIR/data/scenes/column-tiny.toml --set points.0.file=c-points.h5 -o ugimp --quiet
  $ latmpm-solve $LATMPM_SOURCE_DIR/data/scenes/column-tiny.toml --set points.0.file=c-points.h5 --set grid.shape=bspline2 -o bspline2 --quiet
  $ latmpm-solve $LATMPM_SOURCE_DIR/data/scenes/column-tiny.toml --set points.0.file=c-points.h5 --set run.max_steps=800 -o short --quiet
  $ latmpm-post ugimp bspline2 short -o post --title "Tiny column, cell 0.8 mm"
  $ cut -d, -f1,3,13,28-32 post/metrics.csv
  $ latmpm-post ugimp --label "uGIMP, base reaction=ugimp" --load load_fixed --kind compression -o post-base
  $ grep -A4 '^## Compression' post-base/summary.md
)";

// "A:B" -> two strings.
std::pair<std::string, std::string> split_range(const std::string& text, const std::string& option) {
  const size_t colon = text.find(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 == text.size())
    throw latmpm::InputError(option, "", "'" + text + "' is not FROM:TO");
  return {text.substr(0, colon), text.substr(colon + 1)};
}

int post(int argc, char** argv) {
  using namespace latmpm;
  namespace fs = std::filesystem;
  CommandLine cl("latmpm-post", manual);
  cl.positional_list("RUN_DIR", "run directories written by latmpm-solve -o");
  cl.option("output", "OUT_DIR", "directory for curves, metrics, plots and summary.md (created; files replaced)");
  cl.alias('o', "output");
  cl.repeated_option("label", "NAME=RUN_DIR", "legend name of a run (default: the directory's name)");
  cl.option("load", "COLUMN", "series column used as the load: load_driven, load_fixed, load_record... "
                              "(default: load_driven, else the first non-zero one; impact: load_flyer, load_fixed...)");
  cl.option("kind", "KIND", "compression, impact, column or auto (impact: series with flyer_velocity; "
                            "column: point files of cell 'column')", "auto");
  cl.option("title", "TEXT", "title of the plots and the summary");
  cl.option("euler-k", "K", "effective-length factor of the column ends: 0.5 clamped-clamped, 0.7 clamped-pinned, "
                            "1 pinned-pinned, 2 clamped-free", "0.5");
  cl.option("fit-range", "FROM:TO", "travel range of the initial-stiffness fit, e.g. 0mm:0.5mm, or in percent "
                                    "of each run's final travel, e.g. 20%:100% (default: 0 to half the first "
                                    "peak's travel)");
  cl.repeated_option("reference", "LABEL", "compare every run with this one (a label): comparison.csv with the "
                                            "curve, peak, late-load and Euler errors and the largest KE/SE (make tradeoff)");
  cl.option("window", "LENGTH", "travel window of comparison.csv's windowed load error (default: 1/8 of the "
                                "reference's travel)");
  cl.option("plateau-strain", "FROM:TO", "strain range of the plateau load (ISO 13314: 0.2:0.3 or 0.2:0.4)", "0.2:0.3");
  cl.parse(argc, argv);
  if (!cl.given("output")) throw UsageError("missing -o OUT_DIR");

  // 1. Options.
  post::AnalysisOptions options;
  options.kind = cl.text("kind");
  options.load = cl.text("load");
  options.euler_k = cl.number("euler-k");
  if (!(options.euler_k > 0)) throw InputError("--euler-k", "", "must be positive");
  if (cl.given("fit-range")) {
    auto [from, to] = split_range(cl.text("fit-range"), "--fit-range");
    const bool percent = !from.empty() && from.back() == '%';
    if (percent != (!to.empty() && to.back() == '%'))
      throw InputError("--fit-range", "", "FROM and TO must both be lengths or both percentages of the travel");
    if (percent) {
      auto fraction = [](const std::string& text, const char* which) {
        const double value = parse_quantity(text.substr(0, text.size() - 1), dimension::none, "--fit-range", which);
        if (!(value >= 0 && value <= 100)) throw InputError("--fit-range", which, "must lie within 0% to 100%");
        return value / 100;
      };
      options.compression.fit_from_fraction = fraction(from, "FROM");
      options.compression.fit_to_fraction = fraction(to, "TO");
    } else {
      options.compression.fit_from = parse_quantity(from, dimension::length, "--fit-range", "FROM");
      options.compression.fit_to = parse_quantity(to, dimension::length, "--fit-range", "TO");
    }
    if (!(options.compression.fit_to > options.compression.fit_from ||
          options.compression.fit_to_fraction > options.compression.fit_from_fraction))
      throw InputError("--fit-range", "", "TO must be above FROM");
  }
  {
    auto [from, to] = split_range(cl.text("plateau-strain"), "--plateau-strain");
    options.compression.plateau_from_strain = parse_quantity(from, dimension::none, "--plateau-strain", "FROM");
    options.compression.plateau_to_strain = parse_quantity(to, dimension::none, "--plateau-strain", "TO");
    if (!(options.compression.plateau_from_strain >= 0 &&
          options.compression.plateau_to_strain > options.compression.plateau_from_strain &&
          options.compression.plateau_to_strain < 1))
      throw InputError("--plateau-strain", "", "needs 0 <= FROM < TO < 1");
  }
  const std::vector<std::string> dirs = cl.all("RUN_DIR");
  std::vector<std::string> explicit_labels(dirs.size());
  for (const std::string& given : cl.all("label")) {
    const size_t eq = given.rfind('=');
    if (eq == std::string::npos || eq == 0) throw InputError("--label " + given, "", "expected NAME=RUN_DIR");
    const fs::path target = fs::weakly_canonical(fs::absolute(given.substr(eq + 1)));
    bool found = false;
    for (size_t i = 0; i < dirs.size(); ++i)
      if (fs::weakly_canonical(fs::absolute(dirs[i])) == target) explicit_labels[i] = given.substr(0, eq), found = true;
    if (!found) throw InputError("--label " + given, "", "'" + given.substr(eq + 1) + "' is not one of the run directories");
  }
  const std::vector<std::string> labels = post::default_labels(dirs, explicit_labels);

  // 2. Every run read and analysed before anything is written: a bad directory stops here.
  std::vector<post::RunAnalysis> runs;
  for (size_t i = 0; i < dirs.size(); ++i) {
    post::RunDirectory run = post::read_run_directory(dirs[i]);
    run.label = labels[i];
    runs.push_back(post::analyse_run(std::move(run), options));
  }

  // 3. The report.
  const Provenance provenance = Provenance::for_run("latmpm-post", argc, argv);
  post::ReportContext context;
  context.version = provenance.version;
  context.command_line = provenance.command_line;
  context.created_utc = provenance.created_utc;
  context.title = cl.text("title");
  context.euler_k = options.euler_k;
  context.references = cl.all("reference");
  if (cl.given("window")) {
    context.comparison_window = parse_quantity(cl.text("window"), dimension::length, "--window", "");
    if (!(context.comparison_window > 0)) throw InputError("--window", "", "must be positive");
  }
  for (const std::string& label : context.references)
    if (std::none_of(runs.begin(), runs.end(), [&](const post::RunAnalysis& a) { return a.run.label == label; }))
      throw InputError("--reference " + label, "", "not the label of one of the runs");
  const post::ReportFiles files = post::write_post_report(cl.text("output"), runs, context, post::probe_gnuplot());

  for (const auto& a : runs)
    std::printf("%s: %s (%s), %s, load column %s, %zu rows%s\n", a.run.label.c_str(), a.run.path.c_str(),
                post::to_string(a.run.status), post::to_string(a.kind), a.load_column.c_str(), a.run.series.rows(),
                post::complete(a.run.status) ? "" : ", INCOMPLETE");
  for (const auto& w : files.warnings) std::fprintf(stderr, "latmpm-post: warning: %s\n", w.c_str());
  std::printf("latmpm-post: %zu files -> %s (summary.md)\n", files.written.size(), cl.text("output").c_str());
  return exit_ok;
}

}  // namespace

int main(int argc, char** argv) { return latmpm::run_tool("latmpm-post", argc, argv, post); }
