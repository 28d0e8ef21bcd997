#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include "core/errors.hpp"
#include "core/hdf5_file.hpp"
#include "points/point_set.hpp"
#include "scene/scene.hpp"
#include "scratch_points.hpp"

using namespace latmpm;
namespace fs = std::filesystem;

namespace {

std::string scratch_dir() {
  static const std::string dir = test::scratch_points_dir("scene-reader");
  return dir;
}

// The scene every test starts from; line numbers below refer to it.
const std::string base_scene =
    "[run]\n"                                                             // 1
    "end = { plate_displacement = \"2mm\" }\n"                            // 2
    "[grid]\n"                                                            // 3
    "cell = \"0.4mm\"\n"                                                  // 4
    "shape = \"linear\"\n"                                                // 5
    "[time]\n"                                                            // 6
    "cfl = 0.25\n"                                                        // 7
    "mass_scaling = 6\n"                                                  // 8
    "[[points]]\n"                                                        // 9
    "file = \"pts.h5\"\n"                                                 // 10
    "[bodies.column]\n"                                                   // 11
    "role = \"deformable\"\n"                                             // 12
    "material = { E = \"10MPa\", nu = 0.4, density = \"1.05g/cm^3\" }\n"  // 13
    "[bodies.top]\n"                                                      // 14
    "role = \"driven\"\n"                                                 // 15
    "velocity = [\"0mm/s\", \"0mm/s\", \"-100mm/s\"]\n"                   // 16
    "[output]\n"                                                          // 17
    "series_every = 10\n";                                                // 18

Scene parse(const std::string& text, const std::vector<std::string>& overrides = {}) {
  return parse_scene(text, "scene.toml", scratch_dir(), overrides);
}

// Replaces the whole line `line` (1-based) of the base scene.
std::string with_line(int line, const std::string& replacement) {
  std::istringstream in(base_scene);
  std::string out, l;
  for (int i = 1; std::getline(in, l); ++i) out += (i == line ? replacement : l) + "\n";
  return out;
}

}  // namespace

TEST_CASE("A scene's quantities arrive in SI units", "[scene]") {
  Scene s = parse(base_scene);
  CHECK(s.end.kind == EndCondition::plate_displacement);
  CHECK(s.end.value == Approx(2e-3));
  CHECK(s.settings.cell_size == Approx(4e-4));
  CHECK(s.settings.shape_function == mpm::ShapeFunctionKind::linear);
  CHECK(s.settings.cfl == 0.25);
  CHECK(s.settings.fixed_time_step == 0);
  CHECK(s.settings.mass_scaling == 6);
  REQUIRE(s.bodies.size() == 2);
  CHECK(s.bodies[0].name == "column");  // document order, not alphabetical
  CHECK(s.bodies[0].role == BodyRole::deformable);
  CHECK(s.bodies[0].material.young_modulus == Approx(1e7));
  CHECK(s.bodies[0].material.poisson_ratio == 0.4);
  CHECK(s.bodies[0].material.density == Approx(1050));
  CHECK(s.bodies[1].role == BodyRole::driven);
  CHECK_FALSE(s.bodies[1].has_material);
  CHECK(s.bodies[1].velocity.isApprox(Eigen::Vector3d(0, 0, -0.1)));
  CHECK(s.point_files.at(0).path == (fs::path(scratch_dir()) / "pts.h5").string());
  CHECK(s.series_every == 10);
}

TEST_CASE("Defaults are documented in the resolved scene, which reads back to the same scene", "[scene]") {
  Scene s = parse(base_scene);
  // The base scene's linear shapes default to MUSL (USL inverts particles entering empty
  // cells with them, docs/scene.md); GIMP and DDMP (small-mass nodes handed on) to USL.
  CHECK(s.settings.scheme == mpm::UpdateScheme::musl);
  CHECK(parse(base_scene, {"grid.shape=ugimp"}).settings.scheme == mpm::UpdateScheme::usl);
  CHECK(parse(base_scene, {"grid.shape=ddmp"}).settings.scheme == mpm::UpdateScheme::usl);
  CHECK(s.settings.flip_blend == 0.99);
  CHECK(s.settings.gravity.isZero());
  CHECK(s.snapshot_every == 0);
  CHECK(s.settings.record_tag == "record");
  // The default tag is not the scene's request: point files without it are fine.
  CHECK(s.record_where.empty());
  CHECK_FALSE(parse(base_scene, {"output.record_tag=top"}).record_where.empty());
  // Nor in the resolved scene, which names it (a --resume reads it: a run without record points).
  CHECK(parse_scene(s.resolved_toml, "resolved.toml", "/nonexistent").record_where.empty());
  CHECK_THAT(s.resolved_toml, Catch::Contains("scheme = 'musl'") || Catch::Contains("scheme = \"musl\""));
  CHECK_THAT(s.resolved_toml, Catch::Contains("record_tag"));

  // The resolved text is a complete scene: read from anywhere it gives the same values.
  Scene again = parse_scene(s.resolved_toml, "resolved.toml", "/nonexistent");
  CHECK(again.resolved_toml == s.resolved_toml);
  CHECK(again.point_files.at(0).path == s.point_files.at(0).path);
  CHECK(again.settings.cell_size == s.settings.cell_size);
  CHECK(again.bodies[1].velocity == s.bodies[1].velocity);
  CHECK(again.settings.mass_scaling == s.settings.mass_scaling);
}

TEST_CASE("Scene errors name the file, the line and the key", "[scene]") {
  struct Case {
    int line;
    std::string replacement, location, key, problem;
  };
  auto c = GENERATE(values<Case>({
      {13, "material = { E = \"10\", nu = 0.4, density = \"1050kg/m^3\" }", "scene.toml:13",
       "bodies.column.material.E", "has no unit"},
      {13, "material = { E = 10, nu = 0.4, density = \"1050kg/m^3\" }", "scene.toml:13",
       "bodies.column.material.E", "has no unit"},
      {13, "material = { E = \"10mm\", nu = 0.4, density = \"1050kg/m^3\" }", "scene.toml:13",
       "bodies.column.material.E", "expected a"},
      {13, "material = { E = \"10MPa\", nu = 0.4, densty = \"1050kg/m^3\" }", "scene.toml:13",
       "bodies.column.material.densty", "unknown key"},
      {7, "cfll = 0.3", "scene.toml:7", "time.cfll", "unknown key"},
      {5, "shape = \"quadratic\"", "scene.toml:5", "grid.shape", "not one of"},
      {4, "cel = \"0.4mm\"", "scene.toml:4", "grid.cel", "unknown key"},
      {12, "role = \"fixed\"\nvelocity = [\"1m/s\", \"0m/s\", \"0m/s\"]", "scene.toml:13",
       "bodies.column.velocity", "only driven bodies"},
      {12, "", "scene.toml:11", "bodies.column.role", "missing"},
      {16, "velocity = [\"0mm/s\", \"-100mm/s\"]", "scene.toml:16", "bodies.top.velocity",
       "three components"},
      {2, "end = { time = \"1s\", plate_displacement = \"2mm\" }", "scene.toml:2", "run.end",
       "exactly one"},
      {7, "dt = \"1us\"\ncfl = 0.3", "scene.toml:7", "time.dt", "not both"},
      {18, "series_every = 0", "scene.toml:18", "output.series_every", "at least 1"},
      {10, "file = \"missing.h5\"", "scene.toml:10", "points.0.file", "cannot find"},
      {18, "series_every = 10\n[bodies.top2]\nrole = \"driven\"\nvelocity = [\"1m/s\", \"0m/s\", \"0m/s\"]",
       "scene.toml:2", "run.end.plate_displacement", "exactly one driven"},
      {8, "mass_scaling = [6]", "scene.toml:8", "time.mass_scaling", "found an array"},
      {16, "velocity = [\"0mm/s\", \"0mm/s\" \"-1m/s\"]", "scene.toml:16", "", "not valid TOML"},
      {16, "velocity = [\"0mm/s\", \"0mm/s\", \"-100mm/s\"]\nhold = { tag = \"record\" }", "scene.toml:17",
       "bodies.top.hold.tag", "only deformable bodies"},
      {12, "role = \"deformable\"\nhold = { tag = \"\" }", "scene.toml:13", "bodies.column.hold.tag", "must name"},
      {12, "role = \"deformable\"\nhold = { tags = \"record\" }", "scene.toml:13", "bodies.column.hold.tags",
       "unknown key"},
      {15, "role = \"omitted\"", "scene.toml:16", "bodies.top.velocity", "unknown key"},
  }));
  CAPTURE(c.replacement);
  try {
    parse(with_line(c.line, c.replacement));
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.where() == c.location);
    CHECK(e.field() == c.key);
    CHECK_THAT(e.problem(), Catch::Contains(c.problem));
  }
}

TEST_CASE("A held layer is read with its tag and support, clamped unless it slips", "[scene]") {
  const bool slip = GENERATE(false, true);
  const std::string hold = slip ? "hold = { tag = \"record\", slip = true }" : "hold = { tag = \"record\" }";
  Scene s = parse(with_line(12, "role = \"deformable\"\n" + hold));
  const BodySpec* column = s.body("column");
  REQUIRE(column);
  CHECK(column->hold_tag == "record");
  CHECK(column->hold_slip == slip);
  CHECK(column->hold_where == "scene.toml:13");
  // The resolved scene keeps it, the default filled in.
  const Scene again = parse_scene(s.resolved_toml, "resolved.toml", "/nonexistent");
  CHECK(again.body("column")->hold_tag == "record");
  CHECK(again.body("column")->hold_slip == slip);
  CHECK(parse(base_scene).body("column")->hold_tag.empty());
}

TEST_CASE("Command-line overrides reach any field, the value read as TOML or else as text", "[scene]") {
  Scene s = parse(base_scene, {"grid.cell=0.2mm", "time.mass_scaling=1", "grid.scheme=musl",
                               "bodies.top.velocity=[\"0m/s\",\"0m/s\",\"-0.05m/s\"]",
                               "run.end={ time = \"3ms\" }", "output.snapshot_every=5"});
  CHECK(s.settings.cell_size == Approx(2e-4));
  CHECK(s.settings.mass_scaling == 1);
  CHECK(s.settings.scheme == mpm::UpdateScheme::musl);
  CHECK(s.bodies[1].velocity.z() == Approx(-0.05));
  CHECK(s.end.kind == EndCondition::time);
  CHECK(s.end.value == Approx(3e-3));
  CHECK(s.snapshot_every == 5);
  CHECK_THAT(s.resolved_toml, Catch::Contains("0.2mm"));
  CHECK(parse(base_scene, {"grid.ddmp_small_mass_fraction=0.1"}).settings.ddmp_small_mass_fraction == 0.1);

  // Arrays are indexed by number, as in points.0.file; a relative path typed on the command
  // line is relative to the current directory, not to the scene's.
  const fs::path cwd = fs::current_path();
  fs::current_path(fs::path(scratch_dir()).parent_path());
  Scene p = parse_scene(base_scene, "scene.toml", "/nonexistent",
                        {"points.0.file=" + fs::path(scratch_dir()).filename().string() + "/pts.h5"});
  fs::current_path(cwd);
  REQUIRE(p.point_files.size() == 1);
  CHECK(p.point_files[0].path == (fs::path(scratch_dir()) / "pts.h5").string());
}

TEST_CASE("Errors in overridden values name the --set option", "[scene]") {
  auto [assignment, key, problem] = GENERATE(table<std::string, std::string, std::string>({
      {"grid.cell=0.4", "grid.cell", "has no unit"},
      {"grid.cellsize=0.4mm", "grid.cellsize", "unknown key"},
      {"bodies.column.material.nu=0.7", "bodies.column.material.nu", "(-1, 0.5)"},
      {"points.3.file=x.h5", "points.3.file", "past the end"},
      {"grid.cell.x=1", "grid.cell.x", "not a table"},
      {"grid.ddmp_small_mass_fraction=1", "grid.ddmp_small_mass_fraction", "[0, 1)"},
      // A DDMP study option: with another shape it would be silently ignored.
      {"grid.ddmp_subpoints=true", "grid.ddmp_subpoints", "needs shape"},
      {"novalue", "", "key=value"},
  }));
  try {
    parse(base_scene, {assignment});
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.where() == "--set " + assignment);
    CHECK(e.field() == key);
    CHECK_THAT(e.problem(), Catch::Contains(problem));
  }
}

TEST_CASE("Relative point files resolve against the scene file's directory", "[scene]") {
  const fs::path scene_path = fs::path(scratch_dir()) / "s.toml";
  std::ofstream(scene_path) << base_scene;
  const fs::path cwd = fs::current_path();
  fs::current_path(fs::temp_directory_path());  // not the scene's directory
  Scene s = read_scene(scene_path.string());
  fs::current_path(cwd);
  CHECK(s.point_files.at(0).path == (fs::path(scratch_dir()) / "pts.h5").string());
  CHECK(s.source == scene_path.string());
  CHECK_THROWS_WITH(read_scene((fs::path(scratch_dir()) / "none.toml").string()),
                    Catch::Contains("none.toml") && Catch::Contains("cannot read"));
}

TEST_CASE("A j2 material reads paper B's hardening law with defaults, and other models refuse its keys", "[scene]") {
  const Scene full = parse(with_line(13, "material = { model = \"j2\", E = \"190GPa\", nu = 0.3, density = \"7850kg/m^3\", "
                                         "y0 = \"668MPa\", y_inf = \"887MPa\", eta = 51.6, h = \"285MPa\" }"));
  const mpm::MaterialParameters& m = full.body("column")->material;
  CHECK(m.kind == mpm::MaterialKind::j2);
  CHECK(m.initial_yield == Approx(668e6));
  CHECK(m.saturation_yield == Approx(887e6));
  CHECK(m.saturation_rate == Approx(51.6));
  CHECK(m.linear_hardening == Approx(285e6));
  const Scene plain = parse(with_line(13, "material = { model = \"j2\", E = \"190GPa\", nu = 0.3, density = \"7850kg/m^3\", "
                                          "y0 = \"668MPa\" }"));
  const mpm::MaterialParameters& p = plain.body("column")->material;
  CHECK(p.saturation_yield == Approx(668e6));  // perfect plasticity unless told
  CHECK(p.saturation_rate == 0);
  CHECK(p.linear_hardening == 0);
  CHECK_THROWS_WITH(parse(with_line(13, "material = { model = \"j2\", E = \"190GPa\", nu = 0.3, density = \"7850kg/m^3\" }")),
                    Catch::Contains("scene.toml:13") && Catch::Contains("y0"));
  CHECK_THROWS_WITH(parse(with_line(13, "material = { E = \"10MPa\", nu = 0.4, density = \"1.05g/cm^3\", y0 = \"1MPa\" }")),
                    Catch::Contains("y0"));
  CHECK_THROWS_WITH(parse(with_line(13, "material = { model = \"j2\", E = \"190GPa\", nu = 0.3, density = \"7850kg/m^3\", "
                                        "y0 = \"668MPa\", eta = -1 }")),
                    Catch::Contains("eta"));
}

TEST_CASE("An omitted body is listed apart from the simulated ones and kept in the resolved scene", "[scene]") {
  // The driven plate as a rigid half-space, the body "top" of the point files omitted.
  std::string text = with_line(16, "") + "[rigid_bodies.platen]\nmotion = \"driven\"\nshape = \"half_space\"\n"
                     "point = [\"0mm\", \"0mm\", \"2mm\"]\nnormal = [0, 0, -1]\n"
                     "velocity = [\"0mm/s\", \"0mm/s\", \"-100mm/s\"]\n";
  text.replace(text.find("role = \"driven\""), 15, "role = \"omitted\"");
  const Scene s = parse(text);
  REQUIRE(s.bodies.size() == 1);
  CHECK(s.bodies[0].name == "column");
  REQUIRE(s.omitted_bodies.size() == 1);
  CHECK(s.omitted_bodies[0].name == "top");
  CHECK(s.omitted_bodies[0].where == "scene.toml:15");
  CHECK(s.body("top") == nullptr);
  const Scene again = parse_scene(s.resolved_toml, "resolved.toml", "/nonexistent");
  REQUIRE(again.omitted_bodies.size() == 1);
  CHECK(again.omitted_bodies[0].name == "top");
}

TEST_CASE("Without cfl or dt a scene runs at its shape function's measured cfl, written to the resolved scene", "[scene]") {
  for (const char* shape : {"linear", "ugimp", "ddmp"}) {
    CAPTURE(shape);
    const Scene s = parse(with_line(7, ""), {std::string("grid.shape=") + shape});
    CHECK(s.settings.cfl == default_cfl(s.settings.shape_function));
    CHECK(s.settings.cfl > 0);
    CHECK(s.settings.cfl <= 1);
    CHECK(parse_scene(s.resolved_toml, "resolved.toml", "/nonexistent").settings.cfl == s.settings.cfl);
  }
  // uGIMP's measured limit is above the old fixed 0.3 (docs/tradeoff.md, "Time step").
  CHECK(default_cfl(mpm::ShapeFunctionKind::ugimp) > 0.3);
  CHECK(parse(base_scene).settings.cfl == 0.25);  // a given cfl wins
}
