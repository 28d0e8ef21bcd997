// User text in gnuplot scripts: titles, labels, run names and command lines must reach gnuplot
// as text, never as commands (a newline ending a comment, a backquote, a macro), and plots
// must be whole before they are published.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "post/gnuplot_plot.hpp"
#include "scratch_dir.hpp"

using namespace latmpm;
using namespace latmpm::post;
namespace fs = std::filesystem;

namespace {

const char* const hostile[] = {
    "a\nsystem(\"touch PWNED\")\n#",
    "b`touch PWNED`",
    "c'; system('touch PWNED'); '",
    "d\"; system(\"touch PWNED\"); \"",
    "e\\\nsystem(\"touch PWNED\")",
    "f\rsystem(\"touch PWNED\")",
    "g ends in a backslash \\",
    "h @png_file",
};

// install-deps.sh installs gnuplot; without it latmpm-post only loses the plots.
bool gnuplot_installed(const GnuplotInfo& gnuplot) {
  if (!gnuplot.available) WARN("gnuplot is not installed");
  return gnuplot.available;
}

}  // namespace

TEST_CASE("gnuplot strings are single-quoted with quotes doubled and control characters shown", "[post][plot]") {
  CHECK(gnuplot_quote("plain") == "'plain'");
  CHECK(gnuplot_quote("it's") == "'it''s'");
  CHECK(gnuplot_quote("a\nb\rc\td") == "'a?b?c?d'");
  CHECK(gnuplot_quote("x`y` \"z\" \\") == "'x`y` \"z\" \\'");
  CHECK(gnuplot_comment("a\nb") == "# a?b");
  CHECK(gnuplot_comment("ends \\") == "# ends \\ ");
  CHECK(one_line("tab\tnewline\n") == "tab?newline?");
}

TEST_CASE("gnuplot runs a script full of hostile text without running any of it", "[post][plot]") {
  const GnuplotInfo gnuplot = probe_gnuplot();
  if (!gnuplot_installed(gnuplot)) return;
  const test::ScratchDir scratch("gnuplot-hostile");
  std::ofstream(scratch / "data.csv") << "0,0\n1,1\n";
  PlotSpec plot{"hostile", hostile[0], hostile[1], hostile[2], {}, {}, {}};
  for (const char* text : hostile) {
    plot.series.push_back({"data.csv", 1, 2, text, false});
    plot.references.push_back({0.5, text});
    plot.header_comments.push_back(text);
  }
  std::ofstream(scratch / "hostile.gp") << gnuplot_script(plot, gnuplot.png_terminal);
  const std::string problem = run_gnuplot(scratch.string(), "hostile.gp", "out.png", "out.svg");
  CHECK(problem.empty());
  CHECK_FALSE(fs::exists(scratch / "PWNED"));
  CHECK(png_is_complete(scratch / "out.png"));
  CHECK(svg_is_complete(scratch / "out.svg"));
  // The titles arrive as text: the SVG shows them (control characters as '?').
  std::ifstream svg(scratch / "out.svg");
  const std::string text((std::istreambuf_iterator<char>(svg)), std::istreambuf_iterator<char>());
  CHECK(text.find("b`touch PWNED`") != std::string::npos);
}

TEST_CASE("A plot cut short (a full disk) is recognised as incomplete", "[post][plot]") {
  const GnuplotInfo gnuplot = probe_gnuplot();
  if (!gnuplot_installed(gnuplot)) return;
  const test::ScratchDir scratch("gnuplot-truncated");
  std::ofstream(scratch / "data.csv") << "0,0\n1,1\n";
  PlotSpec plot{"p", "title", "x", "y", {{"data.csv", 1, 2, "line", false}}, {}, {}};
  std::ofstream(scratch / "p.gp") << gnuplot_script(plot, gnuplot.png_terminal);
  REQUIRE(run_gnuplot(scratch.string(), "p.gp", "p.png", "p.svg").empty());
  REQUIRE(png_is_complete(scratch / "p.png"));
  REQUIRE(svg_is_complete(scratch / "p.svg"));
  for (const char* name : {"p.png", "p.svg"}) fs::resize_file(scratch / name, fs::file_size(scratch / name) - 20);
  CHECK_FALSE(png_is_complete(scratch / "p.png"));
  CHECK_FALSE(svg_is_complete(scratch / "p.svg"));
  CHECK_FALSE(png_is_complete(scratch / "missing.png"));
}
