// motion = "scheduled" in [rigid_bodies.<name>]: a velocity schedule against time
// (mpm/motion_schedule.hpp) read with units, written back by the resolved scene, and refused
// with the file, the line and the key when it is malformed.
#include <catch2/catch.hpp>

#include "core/errors.hpp"
#include "scene/scene.hpp"
#include "scratch_points.hpp"

using namespace latmpm;

namespace {

// A column under a scheduled half-space plate; the schedule's knots are lines 15 on.
std::string scheduled_plate(const std::string& knots, const std::string& extra = "") {
  return test::column_scene_head("{ time = \"1ms\" }") +  // 1-9
         "[rigid_bodies.plate]\n"                          // 10
         "motion = \"scheduled\"\n"                        // 11
         "shape = \"half_space\"\n"                        // 12
         "point = [\"0mm\", \"0mm\", \"10mm\"]\n"          // 13
         "normal = [0, 0, -1]\n" +                         // 14
         extra + "schedule = [\n" + knots + "]\n";
}

const std::string load_unload =
    "  { time = \"0s\", velocity = [\"0m/s\", \"0m/s\", \"0m/s\"] },\n"
    "  { time = \"0.2ms\", velocity = [\"0m/s\", \"0m/s\", \"-100mm/s\"] },\n"
    "  { time = \"0.6ms\", velocity = [\"0m/s\", \"0m/s\", \"100mm/s\"] },\n";

Scene parse(const std::string& text) {
  static const std::string dir = test::scratch_points_dir("schedule-scene");
  return parse_scene(text, "scene.toml", dir);
}

}  // namespace

TEST_CASE("A scheduled rigid body reads its velocity knots with units", "[scene][schedule]") {
  const Scene s = parse(scheduled_plate(load_unload));
  const RigidBodySpec& plate = s.rigid_bodies.at(0);
  CHECK(plate.motion == mpm::RigidMotion::scheduled);
  REQUIRE(plate.schedule.knots.size() == 3);
  CHECK(plate.schedule.knots[1].time == Approx(0.2e-3));
  CHECK(plate.schedule.knots[2].velocity[2] == Approx(0.1));
  CHECK(plate.velocity == Eigen::Vector3d::Zero());  // V(0)
  CHECK_NOTHROW(mpm::validate(plate, plate.where));
  // The resolved scene reads back to the same schedule.
  const Scene again = parse_scene(s.resolved_toml, "resolved.toml", "/nonexistent");
  REQUIRE(again.rigid_bodies.at(0).schedule.knots.size() == 3);
  CHECK(again.rigid_bodies.at(0).schedule.knots[2].time == plate.schedule.knots[2].time);
  CHECK(again.rigid_bodies.at(0).schedule.knots[1].velocity == plate.schedule.knots[1].velocity);
}

TEST_CASE("A malformed schedule is an error naming the file, the line and the key", "[scene][schedule]") {
  struct Case {
    std::string text, where, key, problem;
  };
  const std::string v0 = "velocity = [\"0m/s\", \"0m/s\", \"0m/s\"]";
  auto c = GENERATE_COPY(values<Case>({
      {scheduled_plate("  { time = \"0s\", velocity = [0, 0, -1] },\n"), "scene.toml:16",
       "rigid_bodies.plate.schedule.0.velocity[0]", "has no unit"},
      {scheduled_plate("  { time = 0, " + v0 + " },\n"), "scene.toml:16", "rigid_bodies.plate.schedule.0.time",
       "has no unit"},
      {scheduled_plate("  { time = \"1ms\", " + v0 + " },\n"), "scene.toml:16", "rigid_bodies.plate.schedule.0.time",
       "time 0"},
      {scheduled_plate("  { time = \"0s\", " + v0 + " },\n  { time = \"0s\", " + v0 + " },\n"), "scene.toml:17",
       "rigid_bodies.plate.schedule.1.time", "increase strictly"},
      {scheduled_plate("  { time = \"0s\", " + v0 + ", speed = 1 },\n"), "scene.toml:16",
       "rigid_bodies.plate.schedule.0.speed", "unknown key"},
      {scheduled_plate("  { time = \"0s\", " + v0 + " },\n", "velocity = [\"0m/s\", \"0m/s\", \"1m/s\"]\n"),
       "scene.toml:15", "rigid_bodies.plate.velocity", "from its schedule"},
      {test::column_scene_head("{ time = \"1ms\" }") +
           "[rigid_bodies.plate]\nmotion = \"scheduled\"\nshape = \"half_space\"\n"
           "point = [\"0mm\", \"0mm\", \"10mm\"]\nnormal = [0, 0, -1]\n",
       "scene.toml:10", "rigid_bodies.plate.schedule", "missing"},
      {test::column_scene_head("{ time = \"1ms\" }") +
           "[rigid_bodies.plate]\nmotion = \"fixed\"\nshape = \"half_space\"\n"
           "point = [\"0mm\", \"0mm\", \"0mm\"]\nnormal = [0, 0, 1]\nschedule = [{ time = \"0s\", " + v0 + " }]\n",
       "scene.toml:15", "rigid_bodies.plate.schedule", "only a scheduled body"},
  }));
  CAPTURE(c.text);
  try {
    parse(c.text);
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.where() == c.where);
    CHECK(e.field() == c.key);
    CHECK_THAT(e.problem(), Catch::Contains(c.problem));
  }
}
