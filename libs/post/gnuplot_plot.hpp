// Plots as gnuplot scripts: one .gp per figure, kept beside its PNG and SVG so a user can
// restyle and re-run it (`gnuplot load_displacement.gp` in the plots directory). The script
// names its outputs through the variables png_file and svg_file (defaults: <name>.png/.svg),
// which is how latmpm-post has gnuplot write to temporary names and rename when done.
// User text (titles, labels, run names, command lines) never becomes gnuplot code: strings
// are single-quoted literals (no backquote command substitution, no @macro expansion, no
// escapes) and control characters, which could end a line and start a command, are shown
// as '?' (gnuplot_quote, gnuplot_comment).
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

// gnuplot's text form of a string literal that shows `text` as it is: single-quoted, ' doubled,
// control characters as '?'.
std::string gnuplot_quote(const std::string& text);
// `text` on one line: control characters (newline, carriage return...) as '?'. For every
// line that quotes user text in a script or a CSV comment.
std::string one_line(const std::string& text);
// A comment line "# text" that cannot end early or continue onto the next line.
std::string gnuplot_comment(const std::string& text);

struct GnuplotInfo {
  bool available = false;
  std::string png_terminal;  // "pngcairo" when the build has cairo, else "png"
};
// Probes `gnuplot` on PATH once.
GnuplotInfo probe_gnuplot();

// Runs `gnuplot -e "png_file='..'; svg_file='..'" SCRIPT` in `directory` (no shell between).
// Returns "" on success, else gnuplot's error output (or why it could not start).
std::string run_gnuplot(const std::string& directory, const std::string& script_file,
                        const std::string& png_file, const std::string& svg_file);

// Whether gnuplot finished writing a plot: a PNG ends with its IEND chunk, an SVG with
// </svg>. gnuplot may exit 0 after a write failed (a full disk); such files are not published.
bool png_is_complete(const std::string& path);
bool svg_is_complete(const std::string& path);

}  // namespace latmpm::post
