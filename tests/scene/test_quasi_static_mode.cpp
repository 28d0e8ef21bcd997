// The quasi-static mode (libs/scene/quasi_static_mode.hpp): the mass scaling it picks for a
// bound on the load error, checked against the Mach-number invariance it rests on.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "scene/quasi_static_mode.hpp"
#include "scene/scene.hpp"
#include "scratch_points.hpp"

using namespace latmpm;

namespace {

std::string scratch_dir() {
  static const std::string dir = test::scratch_points_dir("quasi-static");
  return dir;
}

// Paper A's column material at 100 mm/s (Sec. 4) with the mode's table instead of mass_scaling.
std::string scene_text(const std::string& time_table, const std::string& speed = "-100mm/s") {
  return "[run]\nend = { plate_displacement = \"2mm\" }\n[grid]\ncell = \"0.4mm\"\n[time]\n" + time_table +
         "\n[[points]]\nfile = \"pts.h5\"\n[bodies.column]\nrole = \"deformable\"\n"
         "material = { E = \"10MPa\", nu = 0.4, density = \"1050kg/m^3\" }\n"
         "[rigid_bodies.platen]\nmotion = \"driven\"\nshape = \"half_space\"\npoint = [\"0mm\", \"0mm\", \"16mm\"]\n"
         "normal = [0, 0, -1]\nvelocity = [\"0mm/s\", \"0mm/s\", \"" + speed + "\"]\n";
}

Scene parse(const std::string& text) { return parse_scene(text, "scene.toml", scratch_dir()); }

}  // namespace

TEST_CASE("The quasi-static mode picks paper A's mass scaling for the error measured at paper A's Mach number", "[scene][quasi_static]") {
  // Paper A: 100 mm/s at rho = 6 rho0, its wave speed sqrt(P / rho) with P = E (1 - nu) / ((1 + nu)(1 - 2 nu)).
  const double c = std::sqrt(10e6 * 0.6 / (1.4 * 0.2) / (6 * 1050.0));
  CHECK(paper_a_mach() == Approx(0.1 / c));
  const Scene s = parse(scene_text("quasi_static = { load_error = " + std::to_string(quasi_static_load_error(1.0)) + " }"));
  CHECK(s.settings.mass_scaling == Approx(6).epsilon(1e-4));
  CHECK_THAT(s.quasi_static_note, Catch::Contains("picked mass scaling 6"));
}

TEST_CASE("The quasi-static mode keeps the Mach number: twice the plate speed, a quarter of the mass scaling", "[scene][quasi_static]") {
  const std::string mode = "quasi_static = { load_error = 0.05 }";
  const Scene slow = parse(scene_text(mode)), fast = parse(scene_text(mode, "-200mm/s"));
  // M = v sqrt(s) / c0 is what the error depends on (t -> a t, rho -> a^2 rho leaves the run unchanged).
  CHECK(fast.settings.mass_scaling == Approx(slow.settings.mass_scaling / 4));
  CHECK(slow.settings.mass_scaling > 6);  // 5 % allows more than paper A's 2.8 %
}

TEST_CASE("A looser bound never picks a slower run, and the pick stays within the measured range", "[scene][quasi_static]") {
  double previous = 0;
  for (double bound : {0.005, 0.01, 0.02, 0.03, 0.05, 0.1, 0.2, 0.5}) {
    CAPTURE(bound);
    const double ratio = quasi_static_mach_ratio(bound);
    CHECK(ratio >= previous);
    CHECK(ratio <= 2.0);
    if (bound < 0.1048) CHECK(quasi_static_load_error(ratio) == Approx(bound));
    previous = ratio;
  }
}

TEST_CASE("The quasi-static mode and a mass scaling together are refused", "[scene][quasi_static]") {
  try {
    parse(scene_text("mass_scaling = 6\nquasi_static = { load_error = 0.03 }"));
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.field() == "time.quasi_static.load_error");
    CHECK_THAT(e.problem(), Catch::Contains("either"));
  }
  CHECK_THROWS_AS(parse(scene_text("quasi_static = { load_error = 1.5 }")), InputError);
}
