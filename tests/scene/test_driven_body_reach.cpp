// A driven body that never meets material makes a run with zero load: the scene check warns.
#include <catch2/catch.hpp>

#include "scene/driven_body_reach.hpp"

using namespace latmpm;

namespace {

// A 4 mm cube of deformable points (1 mm cells, 1 ppc) on z ∈ [0, 4 mm] and a 1 mm thick
// driven plate of points whose lowest face is at `plate_bottom` (m).
void specimen(Scene& scene, PointSet& points, double plate_bottom) {
  scene.settings.cell_size = points.cell_size = 1e-3;
  points.ppc = 1;
  points.body_names = {"part", "top_plate"};
  scene.bodies.resize(2);
  scene.bodies[0].name = "part";
  scene.bodies[1].name = "top_plate";
  scene.bodies[1].role = BodyRole::driven;
  scene.bodies[1].velocity = {0, 0, -0.1};
  scene.bodies[1].where = "scene.toml:30";
  scene.end.kind = EndCondition::plate_displacement;
  scene.end.value = 2e-3;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      for (int k = 0; k < 4; ++k) points.position.emplace_back((i + 0.5) * 1e-3, (j + 0.5) * 1e-3, (k + 0.5) * 1e-3);
      points.position.emplace_back((i + 0.5) * 1e-3, (j + 0.5) * 1e-3, plate_bottom + 0.5e-3);
    }
  for (const auto& x : points.position) points.body.push_back(x.z() > plate_bottom ? 1 : 0);
  points.half_size.assign(points.position.size(), Eigen::Vector3d::Constant(0.5e-3));
  points.volume.assign(points.position.size(), 1e-9);
}

}  // namespace

TEST_CASE("A driven plate on the part, or reaching it, gives no warning", "[scene]") {
  for (double bottom : {4e-3, 7e-3}) {  // touching; 3 mm above but 2 mm travel + 1 cell reach
    Scene scene;
    PointSet points;
    specimen(scene, points, bottom);
    CHECK(driven_body_warnings(scene, points).empty());
  }
}

TEST_CASE("A driven plate that never reaches the part is named with its gap", "[scene]") {
  Scene scene;
  PointSet points;
  specimen(scene, points, 9e-3);  // 5 mm above, 2 mm travel
  const auto warnings = driven_body_warnings(scene, points);
  REQUIRE(warnings.size() == 1);
  CHECK_THAT(warnings[0], Catch::Contains("scene.toml:30: the driven body 'top_plate' never comes within a cell"));
  CHECK_THAT(warnings[0], Catch::Contains("2 mm of travel (5 mm away"));
  // Moving sideways, it misses the part however far it goes.
  scene.bodies[1].velocity = {0.1, 0, 0};
  CHECK(driven_body_warnings(scene, points).size() == 1);
}

TEST_CASE("A driven rigid half-space is checked along its normal", "[scene]") {
  Scene scene;
  PointSet points;
  specimen(scene, points, 4e-3);
  scene.bodies[1].role = BodyRole::fixed;  // the plate of points stays; a rigid plane drives
  RigidBodySpec plane;
  plane.shape = mpm::RigidShape::half_space;
  plane.name = "platen";
  plane.where = "scene.toml:40";
  plane.plane_normal = {0, 0, -1};  // out of the body, toward the part below
  plane.velocity = {0, 0, -0.1};
  plane.plane_point = {0, 0, 5e-3};  // 1 mm above the part: reached
  scene.rigid_bodies.push_back(plane);
  CHECK(driven_body_warnings(scene, points).empty());
  scene.rigid_bodies[0].plane_point = {0, 0, 10e-3};  // 6 mm above, 2 mm travel
  const auto warnings = driven_body_warnings(scene, points);
  REQUIRE(warnings.size() == 1);
  CHECK_THAT(warnings[0], Catch::Contains("'platen'"));
  CHECK_THAT(warnings[0], Catch::Contains("6 mm away"));
}
