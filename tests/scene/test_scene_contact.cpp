// The `contact` key of [rigid_bodies.<name>]: penalty contact with friction instead of the
// default no-slip coupling; units required; errors name file, line and key. And the rigid
// body at rest, `motion = "fixed"` (a base), which takes no velocity, mass or gravity.
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
  static const std::string dir = test::scratch_points_dir("contact-scene");
  return dir;
}

const std::string driven_motion = "motion = \"driven\"\n";

// A column under a rigid half-space plate; line 11 is the contact line, line 16 the last
// line of `motion_lines` (line 12 on) and `end` line 2's table.
std::string scene_with(const std::string& contact_line,
                       const std::string& motion_lines = driven_motion +
                                                         "shape = \"half_space\"\n"
                                                         "point = [\"0mm\", \"0mm\", \"10mm\"]\n"
                                                         "normal = [0, 0, -1]\n"
                                                         "velocity = [\"0mm/s\", \"0mm/s\", \"-100mm/s\"]\n",
                       const std::string& end = "{ time = \"1ms\" }") {
  return test::column_scene_head(end) +                                           // 1-9
         "[rigid_bodies.plate]\n"                                                  // 10
         + contact_line + "\n" +                                                   // 11
         motion_lines;                                                            // 12-16
}

// The plate as a fixed base under the column (lines 12-15) and `extra` on line 16.
std::string fixed_base_with(const std::string& extra) {
  return scene_with("contact = { model = \"penalty\", friction = 0.3 }",
                    "motion = \"fixed\"\n"                                           // 12
                    "shape = \"half_space\"\n"                                       // 13
                    "point = [\"0mm\", \"0mm\", \"0mm\"]\n"                          // 14
                    "normal = [0, 0, 1]\n"                                           // 15
                        + extra + "\n");                                           // 16
}

Scene parse(const std::string& text) { return parse_scene(text, "scene.toml", scratch_dir()); }

}  // namespace

TEST_CASE("A rigid body couples without slip unless its contact is penalty", "[scene][contact]") {
  const Scene plain = parse(scene_with(""));
  REQUIRE(plain.rigid_bodies.size() == 1);
  CHECK(plain.rigid_bodies[0].coupling == mpm::RigidCoupling::no_slip);

  const Scene penalty = parse(scene_with("contact = { model = \"penalty\", friction = 0.1, stiffness = \"2kN/m\" }"));
  const RigidBodySpec& b = penalty.rigid_bodies.at(0);
  CHECK(b.coupling == mpm::RigidCoupling::penalty);
  CHECK(b.friction == 0.1);
  CHECK(b.contact_stiffness == Approx(2000));
  // The resolved scene reads back to the same contact.
  const Scene again = parse_scene(penalty.resolved_toml, "resolved.toml", "/nonexistent");
  CHECK(again.rigid_bodies.at(0).coupling == mpm::RigidCoupling::penalty);
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

TEST_CASE("A fixed rigid body is a base at rest that is not a driven body", "[scene][contact]") {
  const Scene scene = parse(fixed_base_with(""));
  const RigidBodySpec& base = scene.rigid_bodies.at(0);
  CHECK(base.motion == mpm::RigidMotion::fixed);
  CHECK(base.velocity == Eigen::Vector3d::Zero());
  CHECK(base.coupling == mpm::RigidCoupling::penalty);
  CHECK(base.friction == 0.3);
  const Scene again = parse_scene(scene.resolved_toml, "resolved.toml", "/nonexistent");
  CHECK(again.rigid_bodies.at(0).motion == mpm::RigidMotion::fixed);

  // It does not count as the one driven body run.end.plate_displacement needs.
  try {
    parse(scene_with("", "motion = \"fixed\"\nmin = [\"0mm\", \"0mm\", \"-1mm\"]\nmax = [\"1mm\", \"1mm\", \"0mm\"]\n",
                     "{ plate_displacement = \"1mm\" }"));
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.field() == "run.end.plate_displacement");
    CHECK_THAT(e.problem(), Catch::Contains("the scene has 0"));
  }
}

TEST_CASE("A fixed rigid body given a velocity, a mass or gravity is an error naming the key", "[scene][contact]") {
  struct Case {
    std::string line, key;
  };
  auto c = GENERATE(values<Case>({
      {"velocity = [\"0mm/s\", \"0mm/s\", \"0mm/s\"]", "rigid_bodies.plate.velocity"},  // even at rest
      {"mass = \"1kg\"", "rigid_bodies.plate.mass"},
      {"gravity = false", "rigid_bodies.plate.gravity"},
  }));
  CAPTURE(c.line);
  try {
    parse(fixed_base_with(c.line));
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.where() == "scene.toml:16");
    CHECK(e.field() == c.key);
    CHECK_THAT(e.problem(), Catch::Contains("fixed"));
  }
}

// [contact]: multi-field grid contact between bodies and point groups (mpm/field_contact.hpp).
TEST_CASE("The contact table turns on grid contact with its friction, groups and volume check", "[scene][contact]") {
  const Scene none = parse(test::column_scene_head("{ time = \"1ms\" }"));
  CHECK_FALSE(none.settings.field_contact.enabled);

  const Scene s = parse(test::column_scene_head("{ time = \"1ms\" }") +
                        "[contact]\nfriction = 0.3\ngroups = \"left, right\"\nfill = 0.8\nbond = \"lattice, top_plate\"\n");
  const mpm::FieldContactSettings& c = s.settings.field_contact;
  CHECK(c.enabled);
  CHECK(c.friction == 0.3);
  CHECK(c.groups == std::vector<std::string>{"left", "right"});
  CHECK(c.fill == 0.8);
  CHECK(c.bonded_bodies == std::vector<std::string>{"lattice", "top_plate"});
  const Scene again = parse_scene(s.resolved_toml, "resolved.toml", "/nonexistent");
  CHECK(again.settings.field_contact.groups == c.groups);
  CHECK(again.settings.field_contact.friction == c.friction);

  struct Case {
    std::string line, key, problem;
  };
  auto bad = GENERATE(values<Case>({
      {"friction = -0.1", "contact.friction", "zero or positive"},
      {"fill = 1.5", "contact.fill", "[0, 1]"},
      {"groups = \"a,,b\"", "contact.groups", "empty tag"},
      {"bond = \"a,,b\"", "contact.bond", "empty body"},
      {"frction = 0.1", "contact.frction", "unknown key"},
  }));
  CAPTURE(bad.line);
  try {
    parse(test::column_scene_head("{ time = \"1ms\" }") + "[contact]\n" + bad.line + "\n");
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.where() == "scene.toml:11");
    CHECK(e.field() == bad.key);
    CHECK_THAT(e.problem(), Catch::Contains(bad.problem));
  }
}
