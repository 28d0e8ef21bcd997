#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/command_line.hpp"
#include "synthetic_run.hpp"
#include "scratch_dir.hpp"

using namespace latmpm;
namespace fs = std::filesystem;

namespace {

fs::path scratch() {
  static const fs::path dir = [] {
    const fs::path d = test::process_scratch("post-tool").path();
    // A compression run that finished, and one that failed half-way.
    test::SeriesSpec s;
    for (int i = 0; i <= 200; ++i) {
      const double u = 1e-4 * i;
      s.time.push_back(u / 0.1), s.displacement.push_back(u), s.load.push_back(u <= 1e-3 ? 2000 * u : 2.0);
    }
    test::write_synthetic_run((d / "good").string(), {}, s);
    for (auto* v : {&s.time, &s.displacement, &s.load}) v->resize(80);
    test::SyntheticRun failed;
    failed.status = "failed";
    test::write_synthetic_run((d / "broken").string(), failed, s);
    fs::create_directories(d / "empty");
    return d;
  }();
  return dir;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

struct ToolRun {
  int status;
  std::string out, err;
};

ToolRun run_post(const std::string& args) {
  const fs::path out = scratch() / "stdout.txt", err = scratch() / "stderr.txt";
  const std::string cmd = "cd " + scratch().string() + " && " + LATMPM_BIN_DIR + "/latmpm-post " + args + " >" +
                          out.string() + " 2>" + err.string();
  const int raw = std::system(cmd.c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(out), slurp(err)};
}

bool gnuplot_on_path() { return std::system("command -v gnuplot >/dev/null 2>&1") == 0; }

}  // namespace

TEST_CASE("latmpm-post writes curves, metrics and a summary that names the failed run", "[post]") {
  const ToolRun r = run_post("good broken -o out --label 'stiff foam=good' --title 'Tool test'");
  INFO(r.err);
  REQUIRE(r.status == 0);
  const fs::path out = scratch() / "out";
  for (const char* file : {"summary.md", "metrics.csv", "curves/stiff_foam.load_displacement.csv",
                           "curves/stiff_foam.load_time.csv", "curves/broken.load_time.csv", "plots/load_time.gp"})
    CHECK(fs::is_regular_file(out / file));
  if (gnuplot_on_path()) {
    CHECK(fs::file_size(out / "plots/load_displacement.png") > 1000);
    CHECK(fs::file_size(out / "plots/load_displacement.svg") > 1000);
  }
  const std::string summary = slurp(out / "summary.md");
  CHECK_THAT(summary, Catch::Contains("# Tool test"));
  CHECK_THAT(summary, Catch::Contains("latmpm-post good broken -o out"));
  CHECK_THAT(summary, Catch::Contains("**broken** (`broken`): failed — `status: failed steps=100"));
  CHECK_THAT(summary, Catch::Contains("stopped: numerical failure: step 42"));
  CHECK_THAT(summary, Catch::Contains("| broken (failed, incomplete) |"));
  CHECK_THAT(summary, Catch::Contains("| stiff foam | 2 |"));  // initial stiffness 2000 N/m = 2 N/mm
  CHECK_THAT(r.out, Catch::Contains("broken: broken (failed), compression, load column load_driven, 80 rows, INCOMPLETE"));

  // metrics.csv: provenance comments, a header with units, one row per run.
  std::stringstream metrics(slurp(out / "metrics.csv"));
  std::string line;
  std::vector<std::string> rows;
  while (std::getline(metrics, line))
    if (line.rfind("#", 0) != 0) rows.push_back(line);
  REQUIRE(rows.size() == 3);
  CHECK(rows[0].rfind("label,run_dir,status,kind,load_column,rows[1],end_time[ms],travel[mm]", 0) == 0);
  CHECK(rows[1].rfind("stiff foam,good,finished,compression,load_driven,201,200,20,", 0) == 0);
  CHECK(rows[2].rfind("broken,broken,failed,compression,load_driven,80,", 0) == 0);
  const std::string curve = slurp(out / "curves/stiff_foam.load_displacement.csv");
  CHECK_THAT(curve, Catch::Contains("# command: ") && Catch::Contains("latmpm-post good broken -o out --label 'stiff foam=good'"));
  CHECK_THAT(curve, Catch::Contains("\ndisplacement[mm],load_driven[N]\n0,0\n0.1,0.2\n"));
}

TEST_CASE("latmpm-post refuses a directory that is not a run, with one line and no output", "[post]") {
  const ToolRun r = run_post("good empty -o refused");
  CHECK(r.status == 2);
  CHECK(r.err == "latmpm-post: empty: not a run directory: no series.csv (expected a latmpm-solve -o RUN_DIR)\n");
  CHECK_FALSE(fs::exists(scratch() / "refused"));
}

TEST_CASE("latmpm-post refuses bad options with exit status 2 naming the option", "[post]") {
  using Case = std::pair<std::string, std::string>;
  const Case c = GENERATE(Case{"good -o x --load flyer", "--load flyer: no column 'load_flyer'"},
                          Case{"good -o x --label a=elsewhere", "--label a=elsewhere: 'elsewhere' is not one of"},
                          Case{"good -o x --fit-range 1mm", "--fit-range: '1mm' is not FROM:TO"},
                          Case{"good -o x --fit-range 1:2mm", "--fit-range: FROM: '1' has no unit"},
                          Case{"good -o x --fit-range 20%:1mm", "--fit-range: FROM and TO must both be lengths"},
                          Case{"good -o x --fit-range 20%:120%", "--fit-range: TO: must lie within 0% to 100%"},
                          Case{"good -o x --fit-range 50%:20%", "--fit-range: TO must be above FROM"},
                          Case{"good -o x --plateau-strain 0.3:0.2", "--plateau-strain: needs 0 <= FROM < TO < 1"},
                          Case{"good -o x --kind tension", "--kind: 'tension' is not one of"});
  const ToolRun r = run_post(c.first);
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::Contains(c.second));
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK_FALSE(fs::exists(scratch() / "x"));
}

TEST_CASE("latmpm-post without run directories or output is a usage error", "[post]") {
  CHECK(run_post("-o x").status == 1);
  CHECK(run_post("good").status == 1);
}

TEST_CASE("A list positional takes every remaining argument and is echoed whole", "[post][core]") {
  CommandLine cl("t", "");
  cl.positional_list("DIR", "directories");
  cl.option("output", "P", "out");
  const char* argv[] = {"t", "a", "--output", "o", "b", "c"};
  cl.parse(6, argv);
  CHECK(cl.all("DIR") == std::vector<std::string>{"a", "b", "c"});
  CHECK(cl.resolved() == "t a b c --output o");
  CommandLine none("t", "");
  none.positional_list("DIR", "directories");
  const char* bare[] = {"t"};
  CHECK_THROWS(none.parse(1, bare));
}
