// RUN_DIR/status.toml (libs/run_output/run_status.hpp) as latmpm-solve writes it at the end of
// every run, and `latmpm-solve --list`, checked against what the scene reader accepts.
#include <catch2/catch.hpp>

#include <filesystem>
#include <thread>
#include <toml++/toml.h>

#include "mpm/real.hpp"  // precision_name
#include "solve_tool.hpp"
#include "tiny_column.hpp"

using namespace latmpm;
using namespace latmpm::test;
namespace fs = std::filesystem;

namespace {

toml::table read_status(const fs::path& run) {
  REQUIRE(fs::exists(run / "status.toml"));
  return toml::parse_file((run / "status.toml").string());  // throws on a malformed file
}

double number(const toml::table& status, const char* key) {
  const auto value = status[key].value<double>();
  INFO(key);
  REQUIRE(value.has_value());
  return *value;
}

std::string text(const toml::table& status, const char* key) { return status[key].value_or(std::string("?")); }

// The last row's step of series.csv: the steps the run completed.
double last_series_step(const fs::path& run) {
  const std::string csv = read_text(run / "series.csv");
  const size_t start = csv.rfind('\n', csv.size() - 2) + 1;
  return std::stod(csv.substr(start, csv.find(',', start) - start));
}

std::vector<std::string> listed(const std::string& choice) {
  const ToolRun r = run_solve("--list " + choice);
  REQUIRE(r.status == 0);
  std::vector<std::string> names;
  std::istringstream lines(r.out);
  for (std::string line; std::getline(lines, line);) names.push_back(line);
  return names;
}

}  // namespace

TEST_CASE("A finished run records its end, steps, time and cost in status.toml", "[solve]") {
  const std::string scene = write_scene("tiny.toml", tiny_scene);
  const fs::path run = scratch() / "run-status";
  const ToolRun r = run_solve(scene + " -o " + run.string() + " --quiet --threads 1");
  INFO(r.err);
  REQUIRE(r.status == 0);
  const toml::table status = read_status(run);
  CHECK(text(status, "status") == "finished");
  CHECK(number(status, "exit") == 0);
  CHECK(text(status, "reason").empty());
  // The steps of the series, the scene's end (0.2 mm at 100 mm/s), every point of the file.
  const double steps = number(status, "steps");
  CHECK(steps == last_series_step(run));
  CHECK(number(status, "simulated_time_s") == Approx(2e-3).epsilon(1e-9));
  const double points = number(status, "points");
  CHECK(points == double(tiny_column({}).size()));
  // The rate is points x steps over the stepping loop's wall time, which is part of the run's.
  const double stepping = number(status, "stepping_wall_s");
  CHECK(stepping > 0);
  CHECK(number(status, "wall_s") >= stepping);
  CHECK(number(status, "updates_per_s") == Approx(points * steps / stepping).epsilon(1e-6));
  CHECK(number(status, "cpu_s") > 0);
  CHECK(number(status, "peak_memory_mb") > 1);
  CHECK(text(status, "tool") == "latmpm-solve");
  // The build's particle precision (mpm/real.hpp), which the tool under test was built with.
  CHECK(text(status, "precision") == mpm::precision_name);
  CHECK_THAT(text(status, "command"), Catch::Contains("-o " + run.string()));
  // The machine the cost was measured on: the processor named as /proc/cpuinfo names it, the
  // processors this process may use, and one of the instruction sets a build can target.
  const std::string cpu = text(status, "cpu_model");
  CHECK(cpu != "?");
  const std::string cpuinfo = fs::exists("/proc/cpuinfo") ? read_text("/proc/cpuinfo") : "";
  if (cpuinfo.find("model name") != std::string::npos)
    CHECK_THAT(cpuinfo, Catch::Contains(cpu.substr(0, cpu.find(" (family "))));
  if (cpuinfo.find("cpu family") != std::string::npos)  // x86
    CHECK_THAT(cpu, Catch::Matches(".+ \\(family [0-9]+ model [0-9]+\\)"));
  const double cpus = number(status, "cpus");
  CHECK(cpus >= 1);
  CHECK(cpus <= std::thread::hardware_concurrency());
  CHECK_THAT(text(status, "vector_isa"), Catch::Matches("avx512|avx2|avx|sse2|none"));
}

TEST_CASE("The log names the machine, and the contact fields when the scene has them", "[solve]") {
  const std::string scene = write_scene("tiny-contact.toml", std::string(tiny_scene) + "[contact]\nfriction = 0.3\n");
  const fs::path run = scratch() / "run-log-contact";
  const ToolRun r = run_solve(scene + " -o " + run.string() + " --quiet --threads 1 --set run.max_steps=5");
  INFO(r.err);
  REQUIRE(r.status == 0);
  const std::string log = read_text(run / "log.txt");
  const toml::table status = read_status(run);
  CHECK_THAT(log, Catch::Contains("machine: " + text(status, "cpu_model") + ", "));
  CHECK_THAT(log, Catch::Contains("built for " + text(status, "vector_isa") + ", " + mpm::precision_name + " precision"));
  CHECK_THAT(log, Catch::Contains("contact: a velocity field per body and per point group (none), friction 0.3, fill 0.9"));
  // Without [contact] there is one field and no such line.
  const fs::path single = scratch() / "run-log-single";
  REQUIRE(run_solve(write_scene("tiny.toml", tiny_scene) + " -o " + single.string() + " --quiet --set run.max_steps=5").status == 0);
  CHECK_THAT(read_text(single / "log.txt"), !Catch::Contains("contact:"));
}

TEST_CASE("A numerical failure is recorded in status.toml with exit status 3 and its reason", "[solve]") {
  // CFL 1 is beyond what uGIMP with nu = 0.4 tolerates (test_solve_tool.cpp).
  const std::string scene = write_scene("blowup.toml", tiny_scene);
  const fs::path run = scratch() / "run-status-blowup";
  const ToolRun r = run_solve(scene + " -o " + run.string() + " --quiet --set time.cfl=1 --set output.series_every=1");
  REQUIRE(r.status == 3);
  const toml::table status = read_status(run);
  CHECK(text(status, "status") == "failed");
  CHECK(number(status, "exit") == 3);
  CHECK_THAT(text(status, "reason"), Catch::StartsWith("numerical failure: ") && Catch::Contains("step"));
  // The solver's step count when the failure was found: the series has a row for every step
  // completed, the failing step is counted when it struck at its end.
  const double steps = number(status, "steps");
  CHECK(steps >= last_series_step(run));
  CHECK(steps <= last_series_step(run) + 1);
  CHECK_THAT(read_text(run / "log.txt"), Catch::Contains("status: failed steps=" + std::to_string(int(steps)) + " "));
  CHECK(number(status, "simulated_time_s") > 0);
}

TEST_CASE("Bad input is recorded in status.toml when the run directory exists, and creates none", "[solve]") {
  const std::string scene = write_scene("tiny.toml", tiny_scene);
  const fs::path existing = scratch() / "run-status-bad";
  fs::create_directories(existing);
  ToolRun r = run_solve(scene + " -o " + existing.string() + " --quiet --set grid.cel=1mm");
  CHECK(r.status == 2);
  const toml::table status = read_status(existing);
  CHECK(text(status, "status") == "bad_input");
  CHECK(number(status, "exit") == 2);
  CHECK_THAT(text(status, "reason"), Catch::Contains("grid.cel: unknown key"));
  CHECK(number(status, "steps") == 0);
  // Quotes and backslashes in the reason survive as TOML (the override is pasted into it).
  r = run_solve(scene + " -o " + existing.string() + " --quiet --set 'grid.shape=\"u\\\\gimp\"'");
  CHECK(r.status == 2);
  CHECK_THAT(text(read_status(existing), "reason"), Catch::Contains("u\\gimp"));
  // A directory that does not exist stays so: bad input writes nothing.
  const fs::path missing = scratch() / "run-status-missing";
  CHECK(run_solve(scene + " -o " + missing.string() + " --quiet --set grid.cel=1mm").status == 2);
  CHECK_FALSE(fs::exists(missing));
}

TEST_CASE("A resumed run's status.toml adds up the wall and CPU time of its parts", "[solve]") {
  const std::string scene = write_scene("tiny.toml", tiny_scene);
  const fs::path run = scratch() / "run-status-resume";
  REQUIRE(run_solve(scene + " -o " + run.string() + " --set run.max_steps=110 --quiet --threads 1").status == 0);
  const toml::table first = read_status(run);
  CHECK(text(first, "status") == "max_steps");
  CHECK(number(first, "steps") == 110);
  REQUIRE(run_solve("--resume " + run.string() + " --set run.max_steps=0 --quiet --threads 1").status == 0);
  const toml::table second = read_status(run);
  CHECK(text(second, "status") == "finished");
  CHECK(number(second, "steps") > 110);
  CHECK(number(second, "wall_s") > number(first, "wall_s"));
  CHECK(number(second, "cpu_s") > number(first, "cpu_s"));
  CHECK(number(second, "stepping_wall_s") > number(first, "stepping_wall_s"));
}

TEST_CASE("latmpm-solve --list names exactly the choices the scene reader accepts", "[solve]") {
  const std::string scene = write_scene("tiny.toml", tiny_scene);
  auto check = [&](const std::string& key, const std::string& value) {
    return run_solve(scene + " --set " + key + "=" + value + " --check").status;
  };
  const auto shapes = listed("shapes");
  CHECK(shapes.size() >= 2);
  // (cpdi1 takes hexahedral domains: the tiny scene's voxel points are refused, exit 2)
  for (const auto& s : shapes) CHECK(check("grid.shape", s) == (s == "cpdi1" ? 2 : 0));
  for (const auto& s : listed("schemes")) CHECK(check("grid.scheme", s) == 0);
  // (j2 also needs its initial yield stress, the one key without a default)
  for (const auto& m : listed("materials"))
    CHECK(check("bodies.column.material.model", m + (m == "j2" ? " --set bodies.column.material.y0=1MPa" : "")) == 0);
  // Boundaries are KEY=VALUE choices; the point-body roles can be tried on the tiny scene
  const auto boundaries = listed("boundaries");
  CHECK(std::count(boundaries.begin(), boundaries.end(), "bodies.role=fixed") == 1);
  CHECK(std::count(boundaries.begin(), boundaries.end(), "rigid_bodies.motion=free") == 1);
  // (the tiny scene's base is fixed and its top plate driven, with a velocity)
  for (const auto& b : boundaries)
    if (b.rfind("bodies.role=", 0) == 0)
      CHECK(check(b == "bodies.role=driven" ? "bodies.top_plate.role" : "bodies.bottom_plate.role", b.substr(12)) == 0);
  // A name not listed is refused, and so is a choice --list does not know.
  CHECK(check("grid.shape", "nurbs") == 2);
  const ToolRun r = run_solve("--list colours");
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::Contains("--list") && Catch::Contains("shapes"));
}
