// Errors of a run against a reference run (post/run_comparison.hpp) and the checks of one run
// (post/run_checks.hpp) on synthetic runs whose numbers are known exactly.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "post/report_rows.hpp"
#include "post/run_analysis.hpp"
#include "post/run_checks.hpp"
#include "post/run_comparison.hpp"
#include "post/run_directory.hpp"
#include "synthetic_run.hpp"
#include "scratch_dir.hpp"

using namespace latmpm;
using namespace latmpm::post;
namespace fs = std::filesystem;

namespace {

// A run loaded linearly, F = stiffness u, over 2 mm in 201 rows; kinetic energy a fixed
// fraction of the strain energy F u / 2 (the ratio the quasi-static check must find); the
// external work W such that the balance error |KE + SE − W| / W is 0.1 u / u_end, and the
// solver's own signed energy_error KE + SE − W.
RunAnalysis linear_run(const std::string& name, double stiffness, double ke_fraction, const std::string& cell = "tetrahedral") {
  const fs::path dir = test::process_scratch("comparison").path() / name;
  fs::remove_all(dir);
  test::SeriesSpec s;
  std::vector<double> kinetic, strain, work, error;
  for (int i = 0; i <= 200; ++i) {
    const double u = 1e-5 * i, f = stiffness * u;
    s.time.push_back(1e-4 * i);
    s.displacement.push_back(u);
    s.load.push_back(f);
    strain.push_back(0.5 * f * u);
    kinetic.push_back(ke_fraction * 0.5 * f * u);
    work.push_back((kinetic.back() + strain.back()) / (1 - 0.1 * i / 200.0));
    error.push_back(kinetic.back() + strain.back() - work.back());
  }
  s.extra = {{"kinetic_energy[J]", kinetic}, {"strain_energy[J]", strain}, {"external_work[J]", work},
             {"energy_error[J]", error}};
  test::SyntheticRun spec;
  spec.cell = cell;
  test::write_synthetic_run(dir.string(), spec, s);
  RunDirectory run = read_run_directory(dir.string());
  run.label = name;
  return analyse_run(std::move(run), AnalysisOptions{});
}

// A flyer of mass m striking a linear spring at v0 (no gravity): v = v0 cos ωt up to the
// reversal at t_r = π/(2ω); there the spring loses, unbooked, the fraction 1 − e² of its energy
// and unloads, v = −e v0 sin(ω(t − t_r)), to t = 2 t_r. The series books what the solver
// would: the flyer's kinetic energy, the spring's strain energy, the flyer's work on it W,
// and energy_error = E_flyer + SE − E0 (0 to the reversal, −(1 − e²) E0 after it).
RunAnalysis lossy_spring_impact(double e) {
  const fs::path dir = test::process_scratch("comparison").path() / "impact";
  fs::remove_all(dir);
  const double m = 0.64, v0 = 2, k = 4e4, w = std::sqrt(k / m), tr = M_PI / (2 * w), e0 = 0.5 * m * v0 * v0;
  test::SeriesSpec s;
  std::vector<double> speed, flyer, potential, kinetic, strain, work, error;
  for (int i = 0; i <= 400; ++i) {
    const double t = 2 * tr * i / 400.0, loading = t <= tr;
    const double v = loading ? v0 * std::cos(w * t) : -e * v0 * std::sin(w * (t - tr));
    const double x = loading ? v0 / w * std::sin(w * t) : e * v0 / w * std::cos(w * (t - tr));
    s.time.push_back(t);
    s.displacement.push_back(0);
    s.load.push_back(k * x);
    speed.push_back(v);
    flyer.push_back(0.5 * m * v * v);
    potential.push_back(0);
    kinetic.push_back(0);
    strain.push_back(0.5 * k * x * x);
    work.push_back(e0 - flyer.back());
    error.push_back(flyer.back() + strain.back() - e0);
  }
  s.extra = {{"flyer_velocity[m/s]", speed}, {"flyer_kinetic_energy[J]", flyer},
             {"flyer_potential_energy[J]", potential}, {"kinetic_energy[J]", kinetic},
             {"strain_energy[J]", strain}, {"external_work[J]", work}, {"energy_error[J]", error}};
  test::write_synthetic_run(dir.string(), test::SyntheticRun{}, s);
  RunDirectory run = read_run_directory(dir.string());
  run.label = "impact";
  AnalysisOptions options;
  options.kind = "impact";
  return analyse_run(std::move(run), options);
}

}  // namespace

TEST_CASE("An impact's energy balance is the whole system's over the impact energy, not the material's over its work",
          "[post]") {
  const double e = GENERATE(1.0, 0.9, 0.5);
  const RunAnalysis run = lossy_spring_impact(e);
  const RunChecks c = run_checks(run);
  INFO("restitution " << e);
  // Closed form: the unbooked loss (1 − e²) E0 over the impact energy E0, at the end and at worst.
  CHECK(c.impact_energy_error == Approx(-(1 - e * e)).margin(1e-9));
  CHECK(c.impact_energy_error_worst == Approx(1 - e * e).margin(1e-9));
  // The material's balance |KE + SE − W| / W at the end reads every loss as 100 %: the spring
  // has given back all it kept, so what is left of W is exactly the loss (e = 1: 0/0 → W ≈ 0).
  if (e < 1) CHECK(c.energy_balance_error == Approx(1).epsilon(1e-6));
  const std::string csv = checks_csv({run}, {});
  CHECK_THAT(csv, Catch::Contains(",impact_energy_error[1],impact_energy_error_worst[1]\n"));
}

TEST_CASE("A compression run has no impact energy balance", "[post]") {
  const RunChecks c = run_checks(linear_run("compressed", 1000, 0.3));
  CHECK(std::isnan(c.impact_energy_error));
  CHECK(std::isnan(c.impact_energy_error_worst));
}

TEST_CASE("A run loaded 10 % more than its reference has curve, peak and work errors of 10 %", "[post]") {
  const RunAnalysis reference = linear_run("reference", 1000, 0.01);
  const RunAnalysis stiffer = linear_run("stiffer", 1100, 0.2);
  const RunComparison c = compare_runs(reference, stiffer);
  // Bin means of a line are the line at the bin centres: the L2 ratio is exactly 0.1.
  CHECK(c.curve_error == Approx(0.1).epsilon(1e-9));
  CHECK(c.peak_error == Approx(0.1).epsilon(1e-9));
  CHECK(c.late_error == Approx(0.1).epsilon(1e-9));  // work: the trapezoid rule is exact on a line
  CHECK(std::isnan(c.euler_error));                  // not a column
  CHECK(c.ke_over_se == Approx(0.2).epsilon(1e-9));
  CHECK(c.final_error == Approx(0.1).epsilon(1e-9));  // 1100 / 1000 N/m at the same 2 mm
  // Windows of 0.25 mm (1/8 of the travel): the means are k times the windows' mean travel,
  // 10 % apart; the largest reference mean is the last (half a window, [1.875, 2] mm).
  CHECK(c.window_load_error == Approx(0.1).epsilon(1e-9));
  CHECK(c.window_load_error_at == Approx(2e-3).epsilon(1e-12));
  // A window of 0.5 mm: stations 0.5 ... 2 mm, the same largest error at the end.
  CHECK(compare_runs(reference, stiffer, 0.5e-3).window_load_error == Approx(0.1).epsilon(1e-9));
  // Against itself every error is 0.
  const RunComparison self = compare_runs(reference, reference);
  CHECK(self.curve_error == 0);
  CHECK(self.peak_error == 0);
  CHECK(self.late_error == 0);
  CHECK(self.final_error == 0);
}

TEST_CASE("Column runs are compared by their post-buckling load and against the Euler load", "[post]") {
  const RunAnalysis reference = linear_run("column-ref", 1000, 0, "column");
  const RunAnalysis run = linear_run("column-run", 900, 0, "column");
  REQUIRE(run.column);
  const RunComparison c = compare_runs(reference, run);
  // Mean of F = k u over the last quarter of the travel scales with k.
  CHECK(c.late_error == Approx(-0.1).epsilon(1e-9));
  CHECK(c.euler_error == Approx(run.column->post_buckling_ratio - 1));
  CHECK(c.curve_error == Approx(0.1).epsilon(1e-9));
  // metrics.csv's ripple against the Euler load: F = k u over the last quarter, 51 evenly
  // spaced values, rms k du sqrt((n^2 - 1) / 12) (as in the checks below), over P_E.
  const double ripple = 900 * 1e-5 * std::sqrt((51.0 * 51.0 - 1) / 12);
  const std::vector<MetricCell> cells = metric_cells(run);
  const auto cell = std::find_if(cells.begin(), cells.end(), [](const MetricCell& m) { return m.name == "load_ripple_to_euler"; });
  REQUIRE(cell != cells.end());
  CHECK(std::stod(cell->value) == Approx(ripple / run.column->euler_load).epsilon(1e-5));
}

TEST_CASE("comparison.csv has a row per reference and run and refuses an unknown reference", "[post]") {
  const std::vector<RunAnalysis> runs = {linear_run("a", 1000, 0), linear_run("b", 1100, 0)};
  const std::string csv = comparison_csv(runs, {"a", "b"}, {"made by a test"});
  CHECK_THAT(csv, Catch::Contains("reference,label,curve_error[1],peak_error[1]"));
  CHECK_THAT(csv, Catch::Contains("\na,b,0.1,0.1,0.1,,0,0.1,0.1,2\n"));
  CHECK_THAT(csv, Catch::Contains("\nb,b,0,0,0,,0,0,0,0.25\n"));
  CHECK_THROWS_WITH(comparison_csv(runs, {"c"}, {}), Catch::Contains("--reference: c"));
}

TEST_CASE("The checks find the energy balance error, where it passes 5 %, and the load ripple", "[post]") {
  const RunAnalysis run = linear_run("checked", 1000, 0.3);
  const RunChecks c = run_checks(run);
  CHECK(c.energy_balance_error == Approx(0.1).epsilon(1e-9));
  // 0.1 u / u_end passes 0.05 first at row 101 (u = 1.01 mm); gauge length 40 mm.
  CHECK(c.balance_5pct_strain == Approx(1.01e-3 / 40e-3).epsilon(1e-9));
  CHECK(c.ke_over_se == Approx(0.3).epsilon(1e-9));
  CHECK(c.final_load == Approx(2.0).epsilon(1e-12));  // 1000 N/m x 2 mm
  CHECK(c.energy_error_over_work == Approx(-0.1).epsilon(1e-9));  // signed: the scheme lost energy
  CHECK(c.energy_secant_stiffness == Approx(1000).epsilon(1e-9));  // SE = k u² / 2
  // KE = 0.3 SE on every row: also over the stiffness fit (metrics.csv).
  CHECK(kinetic_over_strain(run, 0, 0.5e-3) == Approx(0.3).epsilon(1e-9));
  CHECK(kinetic_over_strain(run, 3e-3, 4e-3) == 0);  // no rows there
  // F = k u over the last quarter: 51 evenly spaced values, rms about their mean
  // k du sqrt((n^2 - 1) / 12) with du = 0.01 mm.
  CHECK(c.load_ripple == Approx(1000 * 1e-5 * std::sqrt((51.0 * 51.0 - 1) / 12)).epsilon(1e-9));
  const std::string csv = checks_csv({run}, {});
  CHECK_THAT(csv, Catch::Contains("label,energy_balance_error[1],balance_5pct_strain[1],ke_over_se[1]"));
  CHECK_THAT(csv, Catch::Contains("\nchecked,0.1,0.02525,0.3,"));
}
