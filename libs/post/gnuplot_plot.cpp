#include "post/gnuplot_plot.hpp"

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace latmpm::post {

namespace fs = std::filesystem;

namespace {

// Single-quoted for the shell: ' becomes '\''.
std::string shell_quote(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// Exit status of a shell command, -1 when it could not run.
int shell(const std::string& command) {
  const int raw = std::system(command.c_str());
  return raw != -1 && WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

// A colour-blind-safe palette (Okabe & Ito 2008), cycled.
const char* const palette[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                               "#E69F00", "#56B4E9", "#000000", "#F0E442"};

}  // namespace

std::string gnuplot_quote(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '\\' || c == '"') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string gnuplot_script(const PlotSpec& p, const std::string& png_terminal) {
  const size_t entries = p.series.size() + p.references.size();
  const size_t height = 620 + 24 * entries;  // pixels: the legend grows, the axes keep their size
  std::ostringstream s;
  for (const auto& line : p.header_comments) s << "# " << line << "\n";
  s << "# Re-run in this directory: gnuplot " << p.name << ".gp\n"
    << "if (!exists(\"png_file\")) png_file = " << gnuplot_quote(p.name + ".png") << "\n"
    << "if (!exists(\"svg_file\")) svg_file = " << gnuplot_quote(p.name + ".svg") << "\n\n"
    << "set datafile separator comma\n"
    << "set datafile commentschars \"#\"\n"
    << "set title " << gnuplot_quote(p.title) << " noenhanced\n"
    << "set xlabel " << gnuplot_quote(p.x_label) << " noenhanced\n"
    << "set ylabel " << gnuplot_quote(p.y_label) << " noenhanced\n"
    << "set grid lc rgb \"#d0d0d0\"\n"
    // The legend below the axes, one entry per line: long run names never cover the curves.
    << "set key at screen 0.08, screen 0.01 left bottom Left reverse noenhanced box width 2 maxcols 1\n"
    << "set bmargin " << 4 + (entries * 5 + 3) / 4 << "\n"
    << "set xzeroaxis lt -1 lw 0.5\n";
  for (size_t i = 0; i < p.series.size(); ++i)
    s << "set style line " << i + 1 << " lc rgb \"" << palette[i % 8] << "\" lw 2 dt "
      << (p.series[i].dashed ? 2 : 1) << "\n";
  s << "\nplot \\\n";
  bool first = true;
  for (size_t i = 0; i < p.series.size(); ++i) {
    const auto& e = p.series[i];
    s << (first ? "" : ", \\\n") << "  " << gnuplot_quote(e.data_file) << " using " << e.x_column << ":"
      << e.y_column << " with lines ls " << i + 1 << " title " << gnuplot_quote(e.title);
    first = false;
  }
  for (const auto& r : p.references) {
    char y[40];
    std::snprintf(y, sizeof y, "%.9g", r.y);
    s << (first ? "" : ", \\\n") << "  " << y << " with lines lc rgb \"#555555\" lw 1.5 dt 4 title "
      << gnuplot_quote(r.title);
    first = false;
  }
  s << "\n\n"
    << "set terminal " << png_terminal << " size 1200," << height << (png_terminal == "pngcairo" ? " font \",12\"" : "")
    << "\nset output png_file\nreplot\n"
    << "set terminal svg size 1200," << height << " dynamic font \",12\"\nset output svg_file\nreplot\n"
    << "unset output\n";
  return s.str();
}

GnuplotInfo probe_gnuplot() {
  GnuplotInfo info;
  info.available = shell("command -v gnuplot >/dev/null 2>&1") == 0;
  if (info.available)
    info.png_terminal = shell("gnuplot -e 'set terminal pngcairo' >/dev/null 2>&1") == 0 ? "pngcairo" : "png";
  return info;
}

std::string run_gnuplot(const std::string& directory, const std::string& script_file,
                        const std::string& png_file, const std::string& svg_file) {
  const fs::path errors = fs::temp_directory_path() / ("latmpm-post-gnuplot-" + std::to_string(::getpid()) + ".txt");
  const std::string vars = "png_file=" + gnuplot_quote(png_file) + "; svg_file=" + gnuplot_quote(svg_file);
  const std::string command = "cd " + shell_quote(directory) + " && gnuplot -e " + shell_quote(vars) + " " +
                              shell_quote(script_file) + " >/dev/null 2>" + shell_quote(errors.string());
  const int status = shell(command);
  std::ifstream in(errors);
  std::stringstream text;
  text << in.rdbuf();
  in.close();
  fs::remove(errors);
  if (status == 0) return "";
  std::string message = text.str();
  if (message.empty()) message = "gnuplot exited with status " + std::to_string(status);
  return message;
}

}  // namespace latmpm::post
