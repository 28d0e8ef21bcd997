// Plots as gnuplot scripts: one .gp per figure, kept beside its PNG and SVG so a user can
// restyle and re-run it (`gnuplot load_displacement.gp` in the plots directory). The script
// names its outputs through the variables png_file and svg_file (defaults: <name>.png/.svg),
// which is how latmpm-post has gnuplot write to temporary names and rename when done.
#pragma once
#include <string>
#include <vector>

namespace latmpm::post {

struct PlotSeries {
  std::string data_file;  // CSV, relative to the script's directory
  int x_column = 1, y_column = 2;
  std::string title;      // legend entry, printed literally (no gnuplot enhanced text)
  bool dashed = false;    // incomplete runs
};

struct ReferenceLine {  // a horizontal line, e.g. an Euler load
  double y = 0;
  std::string title;
};

struct PlotSpec {
  std::string name;  // file stem: "load_displacement"
  std::string title, x_label, y_label;  // labels carry their units: "displacement (mm)"
  std::vector<PlotSeries> series;
  std::vector<ReferenceLine> references;
  std::vector<std::string> header_comments;  // provenance, one line each
};

// The script text. `png_terminal` is "pngcairo" or "png".
std::string gnuplot_script(const PlotSpec& plot, const std::string& png_terminal);

// gnuplot's text form of a string literal: double-quoted, with \ and " escaped.
std::string gnuplot_quote(const std::string& text);

struct GnuplotInfo {
  bool available = false;
  std::string png_terminal;  // "pngcairo" when the build has cairo, else "png"
};
// Probes `gnuplot` on PATH once.
GnuplotInfo probe_gnuplot();

// Runs `gnuplot -e "png_file='..'; svg_file='..'" SCRIPT` in `directory`. Returns "" on
// success, else gnuplot's error output (or why it could not start).
std::string run_gnuplot(const std::string& directory, const std::string& script_file,
                        const std::string& png_file, const std::string& svg_file);

}  // namespace latmpm::post
