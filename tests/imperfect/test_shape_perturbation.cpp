#include <catch2/catch.hpp>

#include <Eigen/Geometry>
#include <cmath>

#include "core/errors.hpp"
#include "imperfect/direction.hpp"
#include "imperfect/shape_perturbation.hpp"
#include "synthetic_inputs.hpp"

using namespace latmpm;

namespace {

const double amount = 1.28e-3;

double largest_displacement(const PointSet& before, const PointSet& after) {
  double largest = 0;
  for (size_t i = 0; i < before.size(); ++i)
    largest = std::max(largest, (after.position[i] - before.position[i]).norm());
  return largest;
}

ShapePerturbation of_type(ShapeType type) {
  ShapePerturbation p;
  p.type = type;
  p.amount = amount;
  return p;
}

}  // namespace

TEST_CASE("Each paper perturbation moves no point further than the amount, and one point exactly that far",
          "[imperfect]") {
  const ShapeType type = GENERATE(ShapeType::slant_top_layer, ShapeType::slant_lattice, ShapeType::curved_top_base,
                                  ShapeType::bowed_lattice);
  const Eigen::Vector3d direction = GENERATE(Eigen::Vector3d(1, 0, 0), parse_horizontal_direction("30deg", "test"));
  INFO(shape_label(type));
  const PointSet before = test::printed_block();
  PointSet after = before;
  ShapePerturbation p = of_type(type);
  p.direction = direction;
  const ShapeResult r = apply_shape_perturbation(after, p, "block");
  CHECK(largest_displacement(before, after) == Approx(amount).epsilon(1e-9));
  CHECK(r.largest_displacement == Approx(amount).epsilon(1e-9));
  CHECK(r.largest_gradient < 1);

  // Point count, volumes, domains, bodies and tags never change.
  REQUIRE(after.size() == before.size());
  CHECK(after.volume == before.volume);
  CHECK(after.body == before.body);
  CHECK(after.tags == before.tags);
  for (size_t i = 0; i < before.size(); ++i) REQUIRE(after.half_size[i] == before.half_size[i]);

  // Lateral types move along the direction only, C vertically only.
  for (size_t i = 0; i < before.size(); ++i) {
    const Eigen::Vector3d u = after.position[i] - before.position[i];
    if (type == ShapeType::curved_top_base)
      REQUIRE(u.head<2>().norm() == 0.0);
    else
      REQUIRE(u.cross(direction).norm() <= 1e-15);
  }
}

TEST_CASE("Bodies a perturbation does not move keep bit-identical positions", "[imperfect]") {
  const auto [type, body] = GENERATE(std::make_pair(ShapeType::slant_top_layer, 0), std::make_pair(ShapeType::curved_top_base, 0),
                                     std::make_pair(ShapeType::bowed_lattice, 0), std::make_pair(ShapeType::bowed_lattice, 2));
  const PointSet before = test::printed_block();
  PointSet after = before;
  apply_shape_perturbation(after, of_type(type), "block");
  for (size_t i = 0; i < before.size(); ++i)
    if (before.body[i] == body) REQUIRE(after.position[i] == before.position[i]);

  // --bodies restricts B to one body; the others stay exactly in place.
  PointSet only_lattice = before;
  ShapePerturbation b = of_type(ShapeType::slant_lattice);
  b.bodies = {"lattice"};
  apply_shape_perturbation(only_lattice, b, "block");
  for (size_t i = 0; i < before.size(); ++i)
    if (before.body[i] != 1) REQUIRE(only_lattice.position[i] == before.position[i]);
}

TEST_CASE("A shears only the top cell layer and carries the top base rigidly by the amount", "[imperfect]") {
  const PointSet before = test::printed_block();
  PointSet after = before;
  apply_shape_perturbation(after, of_type(ShapeType::slant_top_layer), "block");
  const double layer_bottom = 51.2e-3 - 9.6e-3;
  for (size_t i = 0; i < before.size(); ++i) {
    const double z = before.position[i].z(), ux = after.position[i].x() - before.position[i].x();
    if (z <= layer_bottom) REQUIRE(after.position[i] == before.position[i]);
    else if (before.body[i] == 2) REQUIRE(ux == Approx(amount).epsilon(1e-12));
    else REQUIRE(ux == Approx(amount * (z - layer_bottom) / 9.6e-3).epsilon(1e-12));
  }
}

TEST_CASE("B shears the whole print linearly in height, bases included", "[imperfect]") {
  const PointSet before = test::printed_block();
  PointSet after = before;
  apply_shape_perturbation(after, of_type(ShapeType::slant_lattice), "block");
  // u_x / (z - bottom) is one constant: a shear, zero at the bottom face of the bottom base.
  const double ratio = (after.position[0].x() - before.position[0].x()) / before.position[0].z();
  for (size_t i = 0; i < before.size(); ++i)
    REQUIRE((after.position[i].x() - before.position[i].x()) == Approx(ratio * before.position[i].z()).epsilon(1e-12));
  // The top row reaches the amount: ratio = amount / z of the highest point.
  CHECK(ratio * (169.5 * 0.32e-3) == Approx(amount).epsilon(1e-12));
}

TEST_CASE("C curves the top base so that the largest gap under a flat plate equals the amount", "[imperfect]") {
  const PointSet before = test::printed_block();
  PointSet after = before;
  apply_shape_perturbation(after, of_type(ShapeType::curved_top_base), "block");
  // A flat compressing plate rests on the highest point of the top surface; the gap below it
  // at each point of the top row is the drop of that point.
  double highest = -1, lowest = 1;
  for (size_t i = 0; i < after.size(); ++i)
    if (before.position[i].z() > 54.0e-3) {
      highest = std::max(highest, after.position[i].z());
      lowest = std::min(lowest, after.position[i].z());
    }
  CHECK(highest == before.position.back().z());  // the crest stays where it was
  CHECK(highest - lowest == Approx(amount).epsilon(1e-9));
  // Below the top cell layer nothing moves.
  for (size_t i = 0; i < before.size(); ++i)
    if (before.position[i].z() < 51.2e-3 - 9.6e-3) REQUIRE(after.position[i] == before.position[i]);
}

TEST_CASE("D bows the lattice as a half sine between the bases, largest at mid-height", "[imperfect]") {
  const PointSet before = test::printed_block();
  PointSet after = before;
  apply_shape_perturbation(after, of_type(ShapeType::bowed_lattice), "block");
  const double z0 = 3.2e-3, span = 48e-3, spacing = 0.32e-3;
  double crest_z = 0, crest = 0;
  for (size_t i = 0; i < before.size(); ++i) {
    if (before.body[i] != 1) continue;
    const double z = before.position[i].z(), ux = after.position[i].x() - before.position[i].x();
    const double shape = std::sin(M_PI * (z - z0) / span);
    // The shape is the sine, its scale between the amount and the amount over the sine's
    // value half a point spacing off the crest (where the nearest points sit).
    REQUIRE(ux / shape >= amount * (1 - 1e-12));
    REQUIRE(ux / shape <= amount / std::cos(M_PI * spacing / 2 / span) * (1 + 1e-12));
    if (ux > crest) crest = ux, crest_z = z;
  }
  CHECK(std::abs(crest_z - (z0 + span / 2)) <= spacing);
}

TEST_CASE("The sine imperfection of a column is a sin(n pi z / L) with the largest deflection a", "[imperfect]") {
  const int mode = GENERATE(1, 2, 3);
  const double length = 16e-3, a = 0.02 * length, spacing = 0.2e-3;
  const PointSet before = test::solid_column(length, 0.8e-3, spacing);
  PointSet after = before;
  ShapePerturbation p;
  p.type = ShapeType::sine;
  p.amount = a;
  p.mode = mode;
  p.length = length;
  p.direction = {0, 1, 0};
  apply_shape_perturbation(after, p, "column");
  CHECK(largest_displacement(before, after) == Approx(a).epsilon(1e-9));
  for (size_t i = 0; i < before.size(); ++i) {
    const Eigen::Vector3d u = after.position[i] - before.position[i];
    REQUIRE(u.x() == 0.0);
    REQUIRE(u.z() == 0.0);
    const double shape = std::sin(mode * M_PI * before.position[i].z() / length);
    if (std::abs(shape) < 1e-6) continue;
    REQUIRE(u.y() / shape >= a * (1 - 1e-12));
    REQUIRE(u.y() / shape <= a / std::cos(mode * M_PI * spacing / 2 / length) * (1 + 1e-12));
  }
}

TEST_CASE("Without geometry parameters the frame comes from the bases' extents, with a note", "[imperfect]") {
  const ShapeType type = GENERATE(ShapeType::slant_top_layer, ShapeType::curved_top_base, ShapeType::bowed_lattice);
  const PointSet with = test::printed_block(true);
  PointSet without = test::printed_block(false);
  without.parameters = {{"cells", "1x1x5"}};  // layer count only: layer height = lattice height / 5
  ShapeResult r_with, r_without;
  const auto u_with = shape_displacements(with, of_type(type), "with", &r_with);
  const auto u_without = shape_displacements(without, of_type(type), "without", &r_without);
  CHECK(r_with.notes.empty());
  CHECK_FALSE(r_without.notes.empty());
  for (size_t i = 0; i < u_with.size(); ++i) REQUIRE((u_with[i] - u_without[i]).norm() <= 1e-15);
}

TEST_CASE("A body that is not in the file is refused, naming --bodies", "[imperfect]") {
  PointSet p = test::printed_block();
  ShapePerturbation s = of_type(ShapeType::slant_lattice);
  s.bodies = {"lattice", "middle_plate"};
  CHECK_THROWS_WITH(apply_shape_perturbation(p, s, "block"),
                    Catch::StartsWith("--bodies") && Catch::Contains("middle_plate"));
}

TEST_CASE("An amount whose displacement gradient reaches one is refused before anything moves", "[imperfect]") {
  const ShapeType type = GENERATE(ShapeType::slant_top_layer, ShapeType::curved_top_base, ShapeType::bowed_lattice);
  const PointSet before = test::printed_block();
  PointSet p = before;
  ShapePerturbation s = of_type(type);
  s.amount = 20e-3;  // larger than a 9.6 mm layer, and than 48 mm / pi for the bow
  CHECK_THROWS_WITH(apply_shape_perturbation(p, s, "block"), Catch::StartsWith("--amount"));
  CHECK(p.position == before.position);
}

TEST_CASE("A needs the cell layer height: a file without it is refused unless --layer-height is given",
          "[imperfect]") {
  PointSet p = test::printed_block(false);
  CHECK_THROWS_WITH(apply_shape_perturbation(p, of_type(ShapeType::slant_top_layer), "block"),
                    Catch::Contains("layer_height"));
  ShapePerturbation s = of_type(ShapeType::slant_top_layer);
  s.layer_height = 9.6e-3;
  CHECK_NOTHROW(apply_shape_perturbation(p, s, "block"));
}

TEST_CASE("Type names: letters and the long names are accepted, anything else is refused", "[imperfect]") {
  CHECK(parse_shape_type("C", "--type") == ShapeType::curved_top_base);
  CHECK(parse_shape_type("bowed-lattice", "--type") == ShapeType::bowed_lattice);
  CHECK(parse_shape_type("slant-top-layer", "--type") == ShapeType::slant_top_layer);
  CHECK_THROWS_AS(parse_shape_type("E", "--type"), InputError);
  CHECK_THROWS_WITH(parse_horizontal_direction("z", "--direction"), Catch::StartsWith("--direction"));
  CHECK_THROWS_AS(parse_horizontal_direction("30", "--direction"), InputError);
  CHECK(parse_horizontal_direction("90deg", "--direction").isApprox(Eigen::Vector3d(0, 1, 0)));
}
