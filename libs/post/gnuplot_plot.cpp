#include "post/gnuplot_plot.hpp"

#include <fcntl.h>
#include <sys/wait.h>

#include <cerrno>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>
#include <iterator>
#include <vector>

#include "core/interruption.hpp"

namespace latmpm::post {

namespace fs = std::filesystem;

namespace {

// Exit status of a command run without a shell, -1 when it could not start.
int run_program(const std::vector<std::string>& argv, const std::string& directory, const std::string& stderr_file) {
  const pid_t child = ::fork();
  if (child < 0) return -1;
  if (child == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    const int err = stderr_file.empty() ? null : ::open(stderr_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (null >= 0) ::dup2(null, STDOUT_FILENO);
    if (err >= 0) ::dup2(err, STDERR_FILENO);
    if (!directory.empty() && ::chdir(directory.c_str()) != 0) ::_exit(127);
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    ::execvp(args[0], args.data());
    ::_exit(127);
  }
  set_child_process(child);
  int raw = 0;
  int waited = 0;
  while ((waited = ::waitpid(child, &raw, 0)) < 0 && errno == EINTR) {
  }
  set_child_process(0);
  return waited == child && WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

// A colour-blind-safe palette (Okabe & Ito 2008), cycled.
const char* const palette[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                               "#E69F00", "#56B4E9", "#000000", "#F0E442"};

}  // namespace

std::string one_line(const std::string& text) {
  std::string out = text;
  for (char& c : out)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  return out;
}

std::string gnuplot_quote(const std::string& text) {
  std::string out = "'";
  for (char c : one_line(text)) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

std::string gnuplot_comment(const std::string& text) {
  std::string line = "# " + one_line(text);
  if (line.back() == '\\') line += ' ';  // a final backslash would continue the comment
  return line;
}

std::string gnuplot_script(const PlotSpec& p, const std::string& png_terminal) {
  const size_t entries = p.series.size() + p.references.size();
  const size_t height = 620 + 24 * entries;  // pixels: the legend grows, the axes keep their size
  std::ostringstream s;
  for (const auto& line : p.header_comments) s << gnuplot_comment(line) << "\n";
  s << gnuplot_comment("Re-run in this directory: gnuplot " + p.name + ".gp") << "\n"
    << "if (!exists('png_file')) png_file = " << gnuplot_quote(p.name + ".png") << "\n"
    << "if (!exists('svg_file')) svg_file = " << gnuplot_quote(p.name + ".svg") << "\n\n"
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
  info.available = run_program({"gnuplot", "--version"}, "", "") == 0;
  if (info.available)
    info.png_terminal = run_program({"gnuplot", "-e", "set terminal pngcairo"}, "", "") == 0 ? "pngcairo" : "png";
  return info;
}

std::string run_gnuplot(const std::string& directory, const std::string& script_file,
                        const std::string& png_file, const std::string& svg_file) {
  // gnuplot's messages go to a private file in the plots directory, removed here.
  std::string errors = directory + "/.gnuplot-errors.XXXXXX";
  int slot = -1;
  {
    const SignalsHeld created_and_registered_together;
    const int fd = ::mkstemp(errors.data());
    if (fd < 0) return "cannot create a file in " + directory;
    ::close(fd);
    slot = register_temporary(errors);
  }
  const std::string vars = "png_file=" + gnuplot_quote(png_file) + "; svg_file=" + gnuplot_quote(svg_file);
  const int status = run_program({"gnuplot", "-e", vars, script_file}, directory, errors);
  std::ifstream in(errors);
  std::stringstream text;
  text << in.rdbuf();
  in.close();
  std::remove(errors.c_str());
  unregister_temporary(slot);
  if (status == 0) return "";
  std::string message = text.str();
  if (message.empty()) message = "gnuplot exited with status " + std::to_string(status);
  return message;
}

namespace {
// The last `n` bytes of a file ("" when shorter or unreadable).
std::string tail_bytes(const std::string& path, size_t n) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return "";
  const std::streamoff size = in.tellg();
  if (size < std::streamoff(n)) return "";
  in.seekg(size - std::streamoff(n));
  std::string out(n, '\0');
  in.read(out.data(), std::streamsize(n));
  return in ? out : "";
}
}  // namespace

bool png_is_complete(const std::string& path) {
  // The IEND chunk: length 0, type "IEND", CRC AE 42 60 82 (PNG specification, 11.2.5).
  static const std::string iend("\0\0\0\0IEND\xae\x42\x60\x82", 12);
  return tail_bytes(path, 12) == iend;
}

bool svg_is_complete(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const size_t end = text.find_last_not_of(" \t\r\n");
  return end != std::string::npos && end >= 5 && text.compare(end - 5, 6, "</svg>") == 0;
}

}  // namespace latmpm::post
