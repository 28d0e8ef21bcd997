#include <catch2/catch.hpp>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/hdf5_file.hpp"
#include "core/provenance.hpp"
#include "run_output/snapshot_writer.hpp"
#include "scene/scene.hpp"
#include "solve_tool.hpp"
#include "tiny_column.hpp"

using namespace latmpm;
using latmpm::test::read_text;
using latmpm::test::run_solve;
using latmpm::test::scratch;
using latmpm::test::tiny_scene;
using latmpm::test::ToolRun;
using latmpm::test::write_scene;
namespace fs = std::filesystem;

namespace {

std::vector<std::vector<double>> read_csv(const fs::path& path, std::vector<std::string>* header) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::stringstream hs(line);
  for (std::string cell; std::getline(hs, cell, ',');) header->push_back(cell);
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::stringstream ls(line);
    rows.emplace_back();
    for (std::string cell; std::getline(ls, cell, ',');) rows.back().push_back(std::stod(cell));
  }
  return rows;
}

size_t column(const std::vector<std::string>& header, const std::string& name) {
  for (size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return i;
  FAIL("no column " << name);
  return 0;
}


}  // namespace

TEST_CASE("A run writes a consistent run directory", "[solve]") {
  const std::string scene = write_scene("tiny.toml", tiny_scene);
  const fs::path run = scratch() / "run-ok";
  ToolRun r = run_solve(scene + " -o " + run.string() + " --quiet --threads 1");
  INFO(r.err);
  REQUIRE(r.status == 0);

  // The series: header with units, rows every 25 steps plus the last, plate travel v·t.
  std::vector<std::string> header;
  auto rows = read_csv(run / "series.csv", &header);
  CHECK(header.front() == "step[1]");
  const size_t step = column(header, "step[1]"), time = column(header, "time[s]");
  const size_t disp = column(header, "displacement[m]"), driven = column(header, "load_driven[N]");
  const size_t fixed = column(header, "load_fixed[N]"), work = column(header, "external_work[J]");
  const size_t kinetic = column(header, "kinetic_energy[J]"), strain = column(header, "strain_energy[J]");
  REQUIRE(rows.size() >= 3);
  CHECK(rows.front()[step] == 0);
  for (size_t i = 1; i + 1 < rows.size(); ++i) CHECK(rows[i][step] == 25.0 * i);
  const auto& last = rows.back();
  CHECK(last[time] == Approx(2e-3).epsilon(1e-9));        // 0.2 mm at 100 mm/s
  CHECK(last[disp] == Approx(0.2e-3).epsilon(1e-9));
  for (const auto& row : rows) CHECK(row[disp] == Approx(0.1 * row[time]).margin(1e-15));
  // Compression loads the plate and the base alike (quasi-static: within 25 %), and the work
  // put in is stored as strain and kinetic energy (explicit MPM with FLIP: within 10 %).
  CHECK(last[driven] > 0);
  CHECK(last[fixed] == Approx(last[driven]).epsilon(0.25));
  CHECK(last[kinetic] + last[strain] == Approx(last[work]).epsilon(0.10));

  // series.h5 holds the CSV's numbers, with provenance naming the scene and the points.
  Hdf5File h5((run / "series.h5").string(), Hdf5File::Mode::read);
  auto h5_time = h5.read_doubles("/series/time");
  REQUIRE(h5_time.size() == rows.size());
  CHECK(h5_time.back() == last[time]);
  Provenance prov = read_provenance(h5);
  CHECK(prov.tool == "latmpm-solve");
  CHECK(prov.inputs.size() == 2);
  REQUIRE_FALSE(prov.history.empty());
  CHECK_THAT(prov.history.back(), Catch::Contains("tiny_column()"));

  // Snapshots: step 0, every 100 steps and the last; every one lists every point.
  const std::string xmf = read_text(run / "snapshots.xmf");
  const size_t steps = size_t(last[step]);
  size_t expected = 1 + steps / 100 + (steps % 100 ? 1 : 0);
  size_t frames = 0;
  for (size_t at = 0; (at = xmf.find("<Time ", at)) != std::string::npos; ++at) ++frames;
  CHECK(frames == expected);
  ParticleSnapshot first = read_snapshot((run / "snapshots/snap_000000.h5").string());
  char name[32];
  std::snprintf(name, sizeof name, "snapshots/snap_%06zu.h5", steps);
  ParticleSnapshot final = read_snapshot((run / name).string());
  REQUIRE(final.size() == first.size());
  CHECK(final.time == Approx(2e-3));
  // Point order is the input's: the top plate moved down by exactly the displacement.
  const PointSet points = test::tiny_column({});
  for (size_t i = 0; i < points.size(); ++i)
    if (points.body[i] == 2) CHECK(final.position[3 * i + 2] - first.position[3 * i + 2] == Approx(-0.2e-3));

  // The resolved scene runs as it is, and the log says how the run ended.
  CHECK(run_solve((run / "scene.toml").string() + " --check").status == 0);
  CHECK_THAT(read_text(run / "log.txt"), Catch::Contains("status: finished"));
}

TEST_CASE("Bad scenes exit with status 2 naming the line and key, writing nothing", "[solve]") {
  auto [from, to, location] = GENERATE(table<std::string, std::string, std::string>({
      {"E = \"10MPa\"", "E = \"10\"", "bad.toml:13: bodies.column.material.E"},
      {"[bodies.top_plate]", "[bodies.top_plates]", "bad.toml:10: points.0.file"},
      {"snapshot_every", "snapshot_evry", "bad.toml:21: output.snapshot_evry"},
      {"role = \"fixed\"", "role = \"clamped\"", "bad.toml:15: bodies.bottom_plate.role"},
      // A held layer whose tag no point of the body carries (the column's is "record").
      {"\"1050kg/m^3\" }", "\"1050kg/m^3\" }\nhold = { tag = \"recrod\" }", "bad.toml:14: bodies.column.hold.tag"},
      // The static solver minimises an elastic energy: a model with history has none.
      {"\"1050kg/m^3\" }", "\"1050kg/m^3\", model = \"j2\", y0 = \"1MPa\" }\n[solver]\nkind = \"static\"",
       "bad.toml:12: bodies.column.material.model"},  // the body's location
  }));
  std::string text = tiny_scene;
  text.replace(text.find(from), from.size(), to);
  const std::string scene = write_scene("bad.toml", text);
  const fs::path run = scratch() / "run-bad";
  fs::remove_all(run);
  ToolRun r = run_solve(scene + " -o " + run.string() + " --quiet");
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::Contains(location));
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK_FALSE(fs::exists(run));
}

TEST_CASE("Overrides on the command line are checked like the file", "[solve]") {
  const std::string scene = write_scene("tiny.toml", tiny_scene);
  ToolRun r = run_solve(scene + " --set grid.cel=1mm --check");
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::Contains("--set grid.cel=1mm: grid.cel: unknown key"));
  ToolRun ok = run_solve(scene + " --set grid.shape=linear --check");
  CHECK(ok.status == 0);
  CHECK_THAT(ok.out, Catch::Contains("shape = 'linear'") || Catch::Contains("shape = \"linear\""));
  CHECK(run_solve(scene).status == 1);  // neither -o nor --check
}

TEST_CASE("A run that blows up exits with status 3 and leaves readable outputs", "[solve]") {
  // CFL number 1 is beyond what uGIMP with nu = 0.4 tolerates: the kinetic energy runs away
  // within a few steps (the solver's runaway check, or a particle thrown off the grid).
  const std::string scene = write_scene("blowup.toml", tiny_scene);
  const fs::path run = scratch() / "run-blowup";
  ToolRun r = run_solve(scene + " -o " + run.string() + " --quiet --set output.series_every=1" +
                        " --set output.snapshot_every=2 --set time.cfl=1");
  INFO(r.err);
  CHECK(r.status == 3);
  CHECK_THAT(r.err, Catch::Contains("numerical failure") && Catch::Contains("step"));
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  // Every completed step has its row, in the CSV and in series.h5.
  std::vector<std::string> header;
  auto rows = read_csv(run / "series.csv", &header);
  CHECK(rows.size() >= 3);
  CHECK(Hdf5File((run / "series.h5").string(), Hdf5File::Mode::read).read_doubles("/series/time").size() ==
        rows.size());
  const std::string log = read_text(run / "log.txt");
  CHECK_THAT(log, Catch::Contains("stopped: numerical failure") && Catch::Contains("status: failed"));
  // Every snapshot the XDMF series lists is whole, and so is the state at the failure.
  const std::string xmf = read_text(run / "snapshots.xmf");
  const size_t n = test::tiny_column({}).size();
  int listed = 0;
  for (size_t at = 0; (at = xmf.find("snapshots/snap_", at)) != std::string::npos; at = xmf.find('<', at)) {
    CHECK(read_snapshot((run / xmf.substr(at, xmf.find(':', at) - at)).string()).size() == n);
    ++listed;
  }
  CHECK(listed >= 6 * 2);  // at least two frames of 6 data items each
  CHECK(read_snapshot((run / "snapshots/failure.h5").string()).size() == n);
  CHECK(fs::exists(run / "failure.xmf"));
}

TEST_CASE("A run stopped half-way and resumed gives the same series as one that never stopped", "[solve]") {
  const std::string scene = write_scene("resume.toml", tiny_scene);
  const fs::path whole = scratch() / "run-whole", half = scratch() / "run-half";
  ToolRun r = run_solve(scene + " -o " + whole.string() + " --quiet --threads 2");
  REQUIRE(r.status == 0);
  // Stopped by max_steps between two series rows (a final row at step 110 is written, and
  // dropped again on resume), resumed with another thread count.
  r = run_solve(scene + " -o " + half.string() + " --set run.max_steps=110 --quiet --threads 2");
  INFO(r.err);
  REQUIRE(r.status == 0);
  REQUIRE(fs::exists(half / "checkpoint.h5"));
  std::vector<std::string> header;
  CHECK(read_csv(half / "series.csv", &header).back()[0] == 110);
  r = run_solve("--resume " + half.string() + " --set run.max_steps=0 --quiet --threads 1");
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(read_text(half / "series.csv") == read_text(whole / "series.csv"));
  CHECK(read_text(half / "snapshots.xmf") == read_text(whole / "snapshots.xmf"));
  CHECK_THAT(read_text(half / "log.txt"), Catch::Contains("resumed from checkpoint.h5 at step 110"));
  // A resume needs a checkpoint; a scene with it is a usage error.
  CHECK(run_solve("--resume " + (scratch() / "no-such-run").string() + " --quiet").status == 2);
  CHECK(run_solve(scene + " --resume " + half.string()).status == 1);
  // A fresh run into a directory drops the checkpoint an earlier run left there, so that a
  // later --resume cannot continue the earlier run's state under this run's log and series.
  fs::copy_file(half / "checkpoint.h5", whole / "checkpoint.h5", fs::copy_options::overwrite_existing);
  r = run_solve(scene + " -o " + whole.string() + " --quiet --threads 2");
  REQUIRE(r.status == 0);
  CHECK_FALSE(fs::exists(whole / "checkpoint.h5"));
  CHECK(run_solve("--resume " + whole.string() + " --quiet").status == 2);
}

TEST_CASE("A free rigid flyer writes the flyer columns and conserves its energy", "[solve]") {
  // The flyer replaces the driven plate: a 50 g box resting on the column's top at 1 m/s
  // with gravity; the column stands on the fixed base.
  std::string text = tiny_scene;
  const std::string driven = "[bodies.top_plate]\nrole = \"driven\"\nvelocity = [\"0mm/s\", \"0mm/s\", \"-100mm/s\"]\n";
  REQUIRE(text.find(driven) != std::string::npos);
  text.replace(text.find(driven), driven.size(),
               "[bodies.top_plate]\nrole = \"deformable\"\n"
               "material = { E = \"10MPa\", nu = 0.4, density = \"1050kg/m^3\" }\n"
               "[rigid_bodies.flyer]\nmotion = \"free\"\nmass = \"50g\"\n"
               "min = [\"-5mm\", \"-5mm\", \"10mm\"]\n"
               "max = [\"5mm\", \"5mm\", \"30mm\"]\nvelocity = [\"0m/s\", \"0m/s\", \"-1m/s\"]\n"
               "[gravity]\ng = [\"0m/s^2\", \"0m/s^2\", \"-9.81m/s^2\"]\n");
  text.replace(text.find("plate_displacement = \"0.2mm\""), 29, "time = \"0.5ms\"");
  const std::string scene = write_scene("flyer.toml", text);
  const fs::path run = scratch() / "run-flyer";
  ToolRun r = run_solve(scene + " -o " + run.string() + " --quiet --set time.mass_scaling=1");
  INFO(r.err);
  REQUIRE(r.status == 0);
  std::vector<std::string> header;
  auto rows = read_csv(run / "series.csv", &header);
  const size_t v = column(header, "flyer_velocity[m/s]"), ke = column(header, "flyer_kinetic_energy[J]");
  const size_t pe = column(header, "flyer_potential_energy[J]"), load = column(header, "load_flyer[N]");
  const size_t error = column(header, "energy_error[J]");
  CHECK(rows.front()[v] == Approx(1));  // along the loading axis: the flyer's approach
  CHECK(rows.front()[ke] == Approx(0.5 * 0.05 * 1));
  const auto& last = rows.back();
  CHECK(last[load] > 0);               // the column pushes back
  CHECK(last[v] < 1);                  // and slows the flyer down
  CHECK(last[pe] < 0);                 // which has come down
  CHECK(std::abs(last[error]) < 0.02 * rows.front()[ke]);
  // Issue 16's balance, summed here from the columns against the impact energy from the
  // scene's inputs, ½ · 50 g · (1 m/s)² (the column starts at rest, unstressed): flyer kinetic
  // + potential, material kinetic + strain + blend and transfer dissipation, less gravity's work on the
  // material, on every row within 0.2 % (measured: 0.033 %; elastic, no self-contact: only the
  // plate's pick-up of nodes and the transfers lose energy); energy_error is that difference.
  const double impact_energy = 0.5 * 0.05 * 1 * 1;
  const size_t kinetic = column(header, "kinetic_energy[J]"), strain = column(header, "strain_energy[J]");
  const size_t blend = column(header, "blend_dissipation[J]"), gravity = column(header, "gravity_work[J]");
  const size_t transfer = column(header, "transfer_dissipation[J]");
  double worst = 0;
  for (const auto& row : rows) {
    const double total = row[ke] + row[pe] + row[kinetic] + row[strain] + row[blend] + row[transfer] - row[gravity];
    worst = std::max(worst, std::abs(total - impact_energy));
    CHECK(row[error] == Approx(total - impact_energy).margin(1e-9 * impact_energy));
  }
  CHECK(worst < 0.002 * impact_energy);
}

TEST_CASE("A column standing on a fixed rigid base carries its weight in load_fixed", "[solve]") {
  // The tiny column with both plates deformable, resting under gravity on a fixed rigid
  // half-space through its lower face (z = 0), no-slip or in penalty contact. The loading
  // axis is gravity's, so load_fixed = −R·a is the weight M g it carries (compression
  // positive), averaged over the run: the column rings about its static sag, its centre of
  // mass at ≲ ω ρ g L²/(3E) ≈ 1 mm/s (ω ≈ π c/(2L)), which leaves at most 1 % of M g in the
  // mean over 10 ms (v/(g T)); 2 % asserted. The base never moves: displacement stays 0.
  const std::string contact = GENERATE(std::string(), std::string("contact = { model = \"penalty\", friction = 0.5 }\n"));
  std::string text = tiny_scene;
  const std::string bodies_from = "[bodies.bottom_plate]";
  const std::string bodies =
      "[bodies.bottom_plate]\nrole = \"deformable\"\nmaterial = { E = \"10MPa\", nu = 0.4, density = \"1050kg/m^3\" }\n"
      "[bodies.top_plate]\nrole = \"deformable\"\nmaterial = { E = \"10MPa\", nu = 0.4, density = \"1050kg/m^3\" }\n"
      "[rigid_bodies.base]\nmotion = \"fixed\"\nshape = \"half_space\"\npoint = [\"0mm\", \"0mm\", \"0mm\"]\n"
      "normal = [0, 0, 1]\n" + contact +
      "[gravity]\ng = [\"0m/s^2\", \"0m/s^2\", \"-9.81m/s^2\"]\n";
  REQUIRE(text.find(bodies_from) != std::string::npos);
  text.replace(text.find(bodies_from), text.find("[output]") - text.find(bodies_from), bodies);
  text.replace(text.find("plate_displacement = \"0.2mm\""), 29, "time = \"10ms\"");
  text.replace(text.find("series_every = 25"), 17, "series_every = 1");
  const std::string scene = write_scene("fixed-base.toml", text);
  const fs::path run = scratch() / "run-fixed-base";
  ToolRun r = run_solve(scene + " -o " + run.string() + " --quiet --set time.mass_scaling=1");
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK_THAT(read_text(run / "log.txt"), Catch::Contains("rigid body base (fixed half_space"));

  std::vector<std::string> header;
  auto rows = read_csv(run / "series.csv", &header);
  const size_t step = column(header, "step[1]"), dt = column(header, "dt[s]");
  const size_t fixed = column(header, "load_fixed[N]"), disp = column(header, "displacement[m]");
  double impulse = 0, time = 0, travel = 0;
  for (const auto& row : rows) {
    travel = std::max(travel, std::abs(row[disp]));
    if (row[step] == 0) continue;  // the state before the first step: no reaction yet
    impulse += row[dt] * row[fixed];
    time += row[dt];
  }
  double volume = 0;
  for (double v : test::tiny_column({}).volume) volume += v;
  const double weight = 1050 * volume * 9.81;
  INFO("mean load_fixed " << impulse / time << " N over " << time << " s, weight " << weight << " N");
  REQUIRE(rows.size() > 100);  // a row every step
  CHECK(travel == 0);
  CHECK(time == Approx(10e-3).epsilon(1e-9));
  CHECK(impulse / time == Approx(weight).epsilon(0.02));
}

TEST_CASE("A static solve takes its Newton budget and bisections from the scene", "[solve]") {
  // Neo-Hookean: the first increment cannot converge in one Newton step (the step that moves
  // the platen is followed by equilibrium iterations), so the path ends there; each bisection
  // is one more (failing) solve, each starting with a "Newton step 1" line.
  auto run_with = [](int bisections) {
    std::string text = tiny_scene;
    const std::string from = "\"1050kg/m^3\" }", to = "\"1050kg/m^3\", model = \"neo_hookean\" }";
    text.replace(text.find(from), from.size(), to);
    text += "[solver]\nkind = \"static\"\nincrements = 2\nnewton_iterations = 1\nbisections = " +
            std::to_string(bisections) + "\n";
    const std::string name = "budget-" + std::to_string(bisections);
    const std::string scene = write_scene(name + ".toml", text);
    const fs::path run = scratch() / ("run-" + name);
    fs::remove_all(run);
    ToolRun r = run_solve(scene + " -o " + run.string() + " --quiet");
    INFO(r.err);
    CHECK(r.status == 0);  // a path that ends is an answer; status.toml says how it ended
    std::ifstream in(run / "log.txt");
    const std::string log((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    CHECK_THAT(log, Catch::Contains("no convergence in 1 Newton steps"));
    CHECK_THAT(log, Catch::Contains(", 0 increments"));
    size_t solves = 0;
    for (size_t at = log.find("Newton step 1:"); at != std::string::npos; at = log.find("Newton step 1:", at + 1)) ++solves;
    CHECK(log.find("Newton step 2:") == std::string::npos);  // the budget: one step a solve
    return solves;
  };
  const size_t unbisected = run_with(0), bisected = run_with(2);
  CHECK(unbisected >= 1);
  CHECK(bisected > unbisected);  // two more travels tried
}
