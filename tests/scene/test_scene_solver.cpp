// The [solver] table: explicit time stepping by default, the static solve with its keys,
// and errors that name the file, the line and the key.
#include <catch2/catch.hpp>

#include "core/errors.hpp"
#include "scene/scene.hpp"
#include "scratch_points.hpp"

using namespace latmpm;

namespace {
std::string scene_with(const std::string& solver, const std::string& end = "{ plate_displacement = \"1mm\" }") {
  return test::column_scene_head(end) +                                        // 1-9
         "[bodies.plate]\n"                                                    // 10
         "role = \"driven\"\n"                                                 // 11
         "velocity = [\"0mm/s\", \"0mm/s\", \"-1mm/s\"]\n"                     // 12
         "[solver]\n"                                                          // 13
         + solver + "\n";                                                      // 14-
}

Scene parse(const std::string& text) {
  static const std::string dir = test::scratch_points_dir("latmpm-solver-scene-");
  return parse_scene(text, "scene.toml", dir);
}
}  // namespace

TEST_CASE("A scene runs the explicit solver unless [solver] asks for the static one", "[scene]") {
  CHECK(parse(scene_with("")).solver.kind == SolverSpec::explicit_dynamics);
  const Scene s = parse(scene_with("kind = \"static\"\nincrements = 8\nlinear_solver = \"ldlt\"\n"
                                   "tolerance = 1e-9\ncheck_stability = false\nstabilisation = 0.05\n"
                                   "newton_iterations = 20\nbisections = 3\nstall_window = 0"));
  CHECK(s.solver.kind == SolverSpec::static_equilibrium);
  CHECK(s.solver.statics.increments == 8);
  CHECK(s.solver.statics.linear_solver == statics::LinearSolverKind::ldlt);
  CHECK(s.solver.statics.tolerance == 1e-9);
  CHECK_FALSE(s.solver.statics.check_stability);
  CHECK(s.solver.statics.stabilisation == 0.05);
  CHECK(s.solver.statics.newton_iterations == 20);
  CHECK(s.solver.statics.bisections == 3);
  CHECK(s.solver.statics.stall_window == 0);
  const Scene defaults = parse(scene_with("kind = \"static\""));
  CHECK(defaults.solver.statics.stabilisation == 0.1);
  CHECK(defaults.solver.statics.newton_iterations == 50);
  CHECK(defaults.solver.statics.bisections == 6);
  CHECK(defaults.solver.statics.stall_window == 4);
}

TEST_CASE("Static solver errors name the line and the key", "[scene]") {
  auto message = [](const std::string& text) {
    try {
      parse(text);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK_THAT(message(scene_with("kind = \"static\"", "{ time = \"1ms\" }")),
             Catch::Contains("scene.toml:14") && Catch::Contains("plate_displacement"));
  CHECK_THAT(message(scene_with("kind = \"static\"\nincrements = 0")),
             Catch::Contains("scene.toml:15") && Catch::Contains("increments"));
  CHECK_THAT(message(scene_with("kind = \"static\"\nlinear_solver = \"qr\"")),
             Catch::Contains("linear_solver") && Catch::Contains("cholmod"));
  CHECK_THAT(message(scene_with("kind = \"static\"\nstabilisation = -0.1")),
             Catch::Contains("scene.toml:15") && Catch::Contains("stabilisation"));
  CHECK_THAT(message(scene_with("kind = \"static\"\nnewton_iterations = 0")),
             Catch::Contains("scene.toml:15") && Catch::Contains("newton_iterations"));
  CHECK_THAT(message(scene_with("kind = \"static\"\nbisections = -1")),
             Catch::Contains("scene.toml:15") && Catch::Contains("bisections"));
  CHECK_THAT(message(scene_with("kind = \"static\"\nstall_window = -1")),
             Catch::Contains("scene.toml:15") && Catch::Contains("stall_window"));
  CHECK_THAT(message(scene_with("kind = \"static\"\nstall_window = 10001")),
             Catch::Contains("scene.toml:15") && Catch::Contains("stall_window"));
  CHECK_THAT(message(scene_with("kind = \"quasi\"")), Catch::Contains("kind"));
}
