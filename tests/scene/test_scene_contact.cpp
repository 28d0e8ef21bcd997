// The `contact` key of [rigid_bodies.<name>]: penalty contact with friction instead of the
// default no-slip coupling; units required; errors name file, line and key.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "core/errors.hpp"
#include "core/hdf5_file.hpp"
#include "points/point_set.hpp"
#include "scene/scene.hpp"
#include "scratch_points.hpp"

using namespace latmpm;
namespace fs = std::filesystem;

namespace {

std::string scratch_dir() {
  static const std::string dir = test::scratch_points_dir("latmpm-contact-scene-");
  return dir;
}

// A column under a rigid half-space plate; line 11 is the contact line.
std::string scene_with(const std::string& contact_line) {
  return "[run]\n"                                                                 // 1
         "end = { time = \"1ms\" }\n"                                              // 2
         "[grid]\n"                                                                // 3
         "cell = \"1mm\"\n"                                                        // 4
         "[[points]]\n"                                                            // 5
         "file = \"pts.h5\"\n"                                                     // 6
         "[bodies.column]\n"                                                       // 7
         "role = \"deformable\"\n"                                                 // 8
         "material = { E = \"10MPa\", nu = 0.4, density = \"1050kg/m^3\" }\n"      // 9
         "[rigid_bodies.plate]\n"                                                  // 10
         + contact_line + "\n" +                                                   // 11
         "motion = \"driven\"\n"                                                   // 12
         "shape = \"half_space\"\n"                                                // 13
         "point = [\"0mm\", \"0mm\", \"10mm\"]\n"                                  // 14
         "normal = [0, 0, -1]\n"                                                   // 15
         "velocity = [\"0mm/s\", \"0mm/s\", \"-100mm/s\"]\n";                      // 16
}

Scene parse(const std::string& text) { return parse_scene(text, "scene.toml", scratch_dir()); }

}  // namespace

TEST_CASE("A rigid body couples without slip unless its contact is penalty", "[scene][contact]") {
  const Scene plain = parse(scene_with(""));
  REQUIRE(plain.rigid_bodies.size() == 1);
  CHECK(plain.rigid_bodies[0].contact == RigidBodySpec::no_slip);

  const Scene penalty = parse(scene_with("contact = { model = \"penalty\", friction = 0.1, stiffness = \"2kN/m\" }"));
  const RigidBodySpec& b = penalty.rigid_bodies.at(0);
  CHECK(b.contact == RigidBodySpec::penalty);
  CHECK(b.friction == 0.1);
  CHECK(b.contact_stiffness == Approx(2000));
  // The resolved scene reads back to the same contact.
  const Scene again = parse_scene(penalty.resolved_toml, "resolved.toml", "/nonexistent");
  CHECK(again.rigid_bodies.at(0).contact == RigidBodySpec::penalty);
  CHECK(again.rigid_bodies.at(0).contact_stiffness == b.contact_stiffness);

  // Without a stiffness the solver chooses it (0 here); "stick" never slides.
  const Scene stick = parse(scene_with("contact = { model = \"penalty\", friction = \"stick\" }"));
  CHECK(stick.rigid_bodies.at(0).contact_stiffness == 0);
  CHECK(std::isinf(stick.rigid_bodies.at(0).friction));
}

TEST_CASE("Contact errors name the file, the line and the key", "[scene][contact]") {
  struct Case {
    std::string line, key, problem;
  };
  auto c = GENERATE(values<Case>({
      {"contact = { model = \"penalty\", friction = 0.1, stiffness = \"2000\" }", "rigid_bodies.plate.contact.stiffness",
       "has no unit"},
      {"contact = { model = \"penalty\", friction = 0.1, stiffness = 2000 }", "rigid_bodies.plate.contact.stiffness",
       "has no unit"},
      {"contact = { model = \"penalty\", friction = 0.1, stiffness = \"2kPa\" }", "rigid_bodies.plate.contact.stiffness",
       "expected a"},
      {"contact = { model = \"penalty\", friction = -0.1 }", "rigid_bodies.plate.contact.friction", "positive"},
      {"contact = { model = \"penalty\", friction = \"slip\" }", "rigid_bodies.plate.contact.friction", "stick"},
      {"contact = { model = \"penalty\" }", "rigid_bodies.plate.contact.friction", "missing"},
      {"contact = { model = \"glue\" }", "rigid_bodies.plate.contact.model", "not one of"},
      {"contact = { friction = 0.2 }", "rigid_bodies.plate.contact.friction", "only penalty contact"},
      {"contact = { model = \"penalty\", friction = 0.1, stifness = \"1N/m\" }", "rigid_bodies.plate.contact.stifness",
       "unknown key"},
  }));
  CAPTURE(c.line);
  try {
    parse(scene_with(c.line));
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.where() == "scene.toml:11");
    CHECK(e.field() == c.key);
    CHECK_THAT(e.problem(), Catch::Contains(c.problem));
  }
}
