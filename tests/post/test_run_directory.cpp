#include <catch2/catch.hpp>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/errors.hpp"
#include "post/run_analysis.hpp"
#include "post/run_directory.hpp"
#include "post/series_table.hpp"
#include "synthetic_run.hpp"
#include "scratch_dir.hpp"

using namespace latmpm;
using namespace latmpm::post;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
  const fs::path d = test::process_scratch("post-runs").path() / name;
  fs::remove_all(d);
  return d;
}

test::SeriesSpec ramp(size_t rows, double rate = 100) {
  test::SeriesSpec s;
  for (size_t i = 0; i < rows; ++i) {
    s.time.push_back(1e-3 * double(i));
    s.displacement.push_back(1e-4 * double(i));
    s.load.push_back(rate * 1e-4 * double(i));
  }
  return s;
}

}  // namespace

TEST_CASE("A run's status is the last status line of its log", "[post]") {
  using Case = std::pair<std::string, RunStatus>;
  const Case c = GENERATE(Case{"[ 2.0s] status: finished steps=10 time=1", RunStatus::finished},
                          Case{"[ 2.0s] status: failed steps=10", RunStatus::failed},
                          Case{"[ 2.0s] status: max_steps steps=10", RunStatus::max_steps},
                          Case{"[ 2.0s] progress 50 %", RunStatus::unfinished});
  std::string line, reason;
  const std::string log = "[ 0.0s] latmpm-solve 0.1\n[ 1.0s] stopped: numerical failure: J < 0\n" + c.first + "\n";
  CHECK(parse_run_status(log, &line, &reason) == c.second);
  CHECK(reason == "stopped: numerical failure: J < 0");
  if (c.second != RunStatus::unfinished) CHECK(line == c.first.substr(8));
  else CHECK_THAT(line, Catch::Contains("no status line"));
}

TEST_CASE("A run's status.toml, where there is one, says how it ended instead of its log", "[post]") {
  using Case = std::pair<std::string, RunStatus>;
  const Case c = GENERATE(Case{"finished", RunStatus::finished}, Case{"max_steps", RunStatus::max_steps},
                          Case{"failed", RunStatus::failed}, Case{"error", RunStatus::failed},
                          Case{"interrupted", RunStatus::unfinished}, Case{"running", RunStatus::unfinished},
                          Case{"bad_input", RunStatus::unfinished});
  const fs::path dir = scratch("status-toml");
  test::SyntheticRun run;
  run.status = "finished";  // the log says finished; status.toml has the last word
  test::write_synthetic_run(dir.string(), run, ramp(20));
  std::ofstream(dir / "status.toml") << "status = \"" << c.first << "\"\nexit = 3\nreason = \"numerical failure: J < 0\"\n"
                                     << "steps = 42\n";
  const RunDirectory read = read_run_directory(dir.string());
  CHECK(read.status == c.second);
  CHECK(read.status_line == "status.toml: " + c.first + ", 42 steps, exit 3");
  CHECK(read.stop_reason == "stopped: numerical failure: J < 0");
  std::ofstream(dir / "status.toml") << "status = finished\n";  // not TOML: a bare word
  CHECK_THROWS_AS(read_run_directory(dir.string()), InputError);
}

TEST_CASE("Series CSV columns are read with their units; a cut last line is dropped", "[post]") {
  const SeriesTable t = parse_series_csv("time[s],load_driven[N]\n0,0\n0.5,1.25\n1,", "series.csv");
  CHECK(t.names == std::vector<std::string>{"time", "load_driven"});
  CHECK(t.unit("load_driven") == "N");
  CHECK(t.rows() == 2);
  CHECK(t.column("load_driven", "x")[1] == 1.25);
  REQUIRE(t.notes.size() == 1);
  CHECK_THAT(t.notes[0], Catch::Contains("line 4 incomplete"));
  CHECK_THROWS_AS(t.column("flyer_velocity", "x"), InputError);
}

TEST_CASE("Malformed series CSV files are input errors naming the line", "[post]") {
  using Case = std::pair<std::string, std::string>;
  const Case c = GENERATE(Case{"time,load[N]\n0,0\n", "series.csv: line 1: header cell 'time'"},
                          Case{"time[s],load[N]\n0,0\n1,x\n2,2\n", "series.csv: line 3: a value is not a number"},
                          Case{"time[s],load[N]\n0,0,0\n1,1\n", "series.csv: line 2: 3 values, the header has 2"},
                          Case{"", "series.csv: header: empty file"});
  CHECK_THROWS_WITH(parse_series_csv(c.first, "series.csv"), Catch::StartsWith(c.second));
}

TEST_CASE("A directory without the run files is not a run", "[post]") {
  const fs::path d = scratch("not-a-run");
  fs::create_directories(d);
  CHECK_THROWS_WITH(read_run_directory(d.string()),
                    Catch::StartsWith(d.string() + ": not a run directory: no series.csv"));
  CHECK_THROWS_WITH(read_run_directory((d / "missing").string()), Catch::Contains("no such directory"));
}

TEST_CASE("The specimen's mass, modulus and gauge length come from the scene and its point file", "[post]") {
  const fs::path d = scratch("specimen");
  test::SyntheticRun r;
  r.deformable_points = 12, r.point_volume = 2e-9, r.density = 1200, r.youngs_modulus = 8e6;
  test::write_synthetic_run(d.string(), r, ramp(5));
  const RunDirectory run = read_run_directory(d.string());
  CHECK(run.status == RunStatus::finished);
  CHECK(run.series.rows() == 5);
  // Only the deformable body counts, at its real density (mass scaling 6 is numerical).
  CHECK(run.specimen.mass == Approx(12 * 2e-9 * 1200));
  CHECK(run.specimen.mass_scaling == 6);
  CHECK(run.specimen.youngs_modulus == Approx(8e6));
  CHECK(run.specimen.gauge_length == Approx(40e-3));
  CHECK(run.specimen.strut_diameter == Approx(1.6e-3));
  CHECK(run.specimen.cell == "tetrahedral");
  CHECK(run.specimen.notes.empty());
}

TEST_CASE("A run whose point file is gone is still read, without mass or geometry", "[post]") {
  const fs::path d = scratch("no-points");
  test::SyntheticRun r;
  r.write_points = false;
  test::write_synthetic_run(d.string(), r, ramp(5));
  const RunDirectory run = read_run_directory(d.string());
  CHECK(std::isnan(run.specimen.mass));
  CHECK(std::isnan(run.specimen.gauge_length));
  CHECK(run.specimen.youngs_modulus == Approx(10e6));
  REQUIRE_FALSE(run.specimen.notes.empty());
  CHECK_THAT(run.specimen.notes[0], Catch::Contains("point file unreadable"));
}

TEST_CASE("The analysis picks the kind from the point file and the load from the series", "[post]") {
  const fs::path d = scratch("kinds");
  test::SyntheticRun r;
  r.cell = GENERATE(std::string("column"), std::string("tetrahedral"));
  test::write_synthetic_run(d.string(), r, ramp(50));
  const RunAnalysis a = analyse_run(read_run_directory(d.string()), {});
  CHECK(a.kind == (r.cell == "column" ? TestKind::column : TestKind::compression));
  CHECK(a.load_column == "load_driven");
  CHECK(a.has_travel);
  CHECK(a.column.has_value() == (r.cell == "column"));
  REQUIRE(a.compression.has_value());
  CHECK(a.compression->stiffness == Approx(100).epsilon(1e-9));

  AnalysisOptions fixed;
  fixed.load = "fixed";  // shorthand for load_fixed
  CHECK(analyse_run(read_run_directory(d.string()), fixed).load_column == "load_fixed");
  AnalysisOptions wrong;
  wrong.load = "load_flyer";
  CHECK_THROWS_WITH(analyse_run(read_run_directory(d.string()), wrong), Catch::Contains("no column 'load_flyer'"));
  wrong = {};
  wrong.kind = "tension";
  CHECK_THROWS_WITH(analyse_run(read_run_directory(d.string()), wrong), Catch::StartsWith("--kind"));
}

TEST_CASE("The effective modulus is the stiffness times the gauge length over the footprint area", "[post]") {
  // A linear specimen F = k u with k = 100 N/m (ramp), H = 40 mm, A = 2 mm x 5 mm: the block of
  // that footprint and height with E* = k H / A = 400 Pa is as stiff. Also from one increment
  // (two rows: the secant), and not at all without a recorded footprint.
  const fs::path d = scratch("modulus");
  test::SyntheticRun r;
  r.footprint_area = 10e-6;
  const size_t rows = GENERATE(size_t(2), size_t(50));
  test::write_synthetic_run(d.string(), r, ramp(rows));
  const RunAnalysis a = analyse_run(read_run_directory(d.string()), {});
  CHECK(a.run.specimen.footprint_area == Approx(10e-6).epsilon(1e-15));
  REQUIRE(a.compression.has_value());
  CHECK(a.compression->stiffness == Approx(100).epsilon(1e-12));
  CHECK(a.compression->effective_modulus == Approx(100 * 40e-3 / 10e-6).epsilon(1e-12));
  if (rows == 2) {
    CHECK(a.compression->fit_from == 0);
    CHECK(a.compression->fit_to == Approx(1e-4));
    CHECK(std::isnan(a.compression->peak_load));
  }

  r.footprint_area = 0;
  test::write_synthetic_run(d.string(), r, ramp(rows));
  const RunAnalysis bare = analyse_run(read_run_directory(d.string()), {});
  REQUIRE(bare.compression.has_value());
  CHECK(bare.compression->stiffness == Approx(100).epsilon(1e-12));
  CHECK(std::isnan(bare.compression->effective_modulus));
  CHECK(std::any_of(bare.notes.begin(), bare.notes.end(),
                    [](const std::string& n) { return n.find("effective modulus") != std::string::npos; }));
}

TEST_CASE("Impact runs are recognised by their flyer columns", "[post]") {
  const fs::path d = scratch("impact");
  test::SeriesSpec s = ramp(20);
  std::vector<double> v, ke;
  for (size_t i = 0; i < 20; ++i) v.push_back(-2 + 0.25 * double(i)), ke.push_back(5 * v.back() * v.back());
  s.extra = {{"flyer_velocity[m/s]", v}, {"flyer_kinetic_energy[J]", ke}};
  test::write_synthetic_run(d.string(), {}, s);
  const RunAnalysis a = analyse_run(read_run_directory(d.string()), {});
  CHECK(a.kind == TestKind::impact);
  CHECK(a.load_column == "load_fixed");
  REQUIRE(a.impact.has_value());
  CHECK(a.impact->impact_speed == Approx(2));
  CHECK(a.impact->reversal_time == Approx(8e-3));  // v = 0 at row 8
}

TEST_CASE("Labels default to directory names and are made unique", "[post]") {
  CHECK(default_labels({"runs/a/", "b"}, {}) == std::vector<std::string>{"a", "b"});
  CHECK(default_labels({"x/run", "y/run"}, {}) == std::vector<std::string>{"x/run", "y/run"});
  CHECK(default_labels({"x/run", "y/run"}, {"", "mine"}) == std::vector<std::string>{"run", "mine"});
  const std::vector<std::string> same = default_labels({"run", "run"}, {});  // the same directory twice
  CHECK(same[0] != same[1]);
  CHECK(file_stem(same[0]) != file_stem(same[1]));
  CHECK(file_stem("uGIMP, E = 8 MPa") == "uGIMP__E___8_MPa");
  CHECK(file_stem("..") == "run");
}
