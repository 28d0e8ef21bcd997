// Held points (BodySettings::hold_tag): a deformable body clamped by a tagged layer of its own
// points, Paper A Sec. 5.1 ("fixed at the bottom", load from the record points' stress).
#include <catch2/catch.hpp>

#include <cmath>

#include "core/errors.hpp"
#include "mpm/observers.hpp"
#include "mpm/simulation.hpp"
#include "point_builders.hpp"

using namespace latmpm;
using namespace latmpm::mpm;
using namespace latmpm::mpm::test;

namespace {

// A 2×2×8-cell column on z = 0 whose bottom layer of points (one point spacing) carries the
// tag "record", under a one-cell driven plate.
PointSet held_column(Real h) {
  PointSet points = empty_point_set(h, 2);
  add_points(points, Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2 * h, 2 * h, 8 * h), "column");
  add_points(points, Eigen::Vector3d(0, 0, 8 * h), Eigen::Vector3d(2 * h, 2 * h, 9 * h), "plate");
  tag_points(points, "record", [&](size_t p) { return points.body[p] == 0 && points.position[p][2] < h / 2; });
  return points;
}

}  // namespace

TEST_CASE("A column held by its bottom layer carries E·A·strain at the base, the plate and the record layer",
          "[mpm][hold]") {
  const auto shape = GENERATE(ShapeFunctionKind::ugimp, ShapeFunctionKind::cpgimp, ShapeFunctionKind::linear);
  // A power-of-two cell keeps every point and node coordinate exact: a plate point's domain
  // edge then lies exactly on the node plane z = H instead of a round-off below it, where
  // the plate would also take the nodes of the column's top cell.
  const Real h = std::ldexp(1.0, -10), E = 1e7, density = 1000;
  const PointSet points = held_column(h);
  Settings s;
  s.cell_size = h;
  s.shape_function = shape;
  s.cfl = 0.3;
  // ν = 0: uniaxial stress and uniaxial strain coincide, so the clamped ends add no
  // lateral constraint and the column is a patch test of σ_zz = E ε_zz.
  BodySettings column = deformable("column", elastic(E, 0, density));
  column.hold_tag = "record";
  // Quasi-static: the plate speed is 2e-4 of the wave speed c = 100 m/s, so the inertial
  // overshoot ρ c v A is 2 % of the load at the end.
  const Real speed = 0.02, H = 8 * h, A = 4 * h * h;
  Simulation sim(points, {column, rigid("plate", BodyRole::driven, Vec3(0, 0, -speed), density)}, s);
  CHECK(sim.record_area() == Approx(A).epsilon(1e-12));
  // The held nodes are the bottom face z = 0 (and the empty plane below); the plate drives
  // every node its points' stencils touch. A GIMP plate point's domain starts on the node
  // plane z = H and crosses it as soon as the plate moves, so the plate then also drives the
  // nodes z = H − h; linear shapes reach z = H − h only after a quarter cell of travel.
  // Between the constrained planes the strain is uniform: u / length. Compress to 1 %,
  // averaging the loads over the last fifth of the run (several wave transits: the
  // ringing averages out).
  const Real length = shape == ShapeFunctionKind::linear ? H : H - h;
  const Real end = 0.01 * H / speed;
  Real base = 0, plate = 0, record = 0, expected = 0;
  int samples = 0;
  const RecordLayerForce record_force(sim);
  sim.add_observer([&](const Simulation& m, const StepDiagnostics& d) {
    if (d.time < 0.8 * end) return;
    base += d.reaction[0][2];       // the held nodes push the column up
    plate += -d.reaction[1][2];     // the plate pushes it down
    record += -record_force(m);     // compression positive
    expected += E * A * speed * d.time / length;
    ++samples;
    (void)m;
  });
  sim.run_until(end);
  REQUIRE(samples > 20);
  INFO("shape " << to_string(shape) << ": base " << base / samples << " N, plate " << plate / samples
                << " N, record " << record / samples << " N, E A strain " << expected / samples << " N");
  CHECK(base == Approx(plate).epsilon(0.01));  // equilibrium of the column as a whole
  CHECK(base == Approx(expected).epsilon(0.03));
  CHECK(plate == Approx(expected).epsilon(0.03));
  CHECK(record == Approx(expected).epsilon(0.03));
  // The held layer itself deforms (that is what lets it record): its points moved down.
  const Particles& ps = sim.particles();
  for (size_t p = 0; p < ps.size(); ++p)
    if (ps.flags[p] & Particles::held_flag) CHECK(ps.position[p][2] < h / 4);
}

TEST_CASE("A Poisson column: a clamped held face stiffens the record layer, a slipping one reads the load",
          "[mpm][hold]") {
  const bool slip = GENERATE(false, true);
  const Real h = std::ldexp(1.0, -10), E = 1e7, nu = 0.4, density = 1000;
  const PointSet points = held_column(h);
  Settings s;
  s.cell_size = h;
  BodySettings column = deformable("column", elastic(E, nu, density));
  column.hold_tag = "record";
  column.hold_slip = slip;
  // As above, with the paper's ν = 0.4 (REFERENCE.md, Sec. 5).
  const Real speed = 0.02, H = 8 * h, A = 4 * h * h, end = 0.01 * H / speed;
  Simulation sim(points, {column, rigid("plate", BodyRole::driven, Vec3(0, 0, -speed), density)}, s);
  Real base = 0, plate = 0, record = 0, expected = 0;
  int samples = 0;
  const RecordLayerForce record_force(sim);
  sim.add_observer([&](const Simulation& m, const StepDiagnostics& d) {
    if (d.time < 0.8 * end) return;
    base += d.reaction[0][2];
    plate += -d.reaction[1][2];
    record += -record_force(m);
    expected += E * A * speed * d.time / (H - h);
    ++samples;
  });
  sim.run_until(end);
  REQUIRE(samples > 20);
  INFO((slip ? "slipping" : "clamped") << ": base " << base / samples << " N, plate " << plate / samples
                                       << " N, record " << record / samples << " N, E A strain "
                                       << expected / samples << " N");
  CHECK(base == Approx(plate).epsilon(0.01));  // equilibrium of the column as a whole
  if (slip) {
    // Free to expand sideways at the base, the record layer is in uniaxial stress like the
    // rest: it reads the load, and the load is E·A·strain (the plate-end constraint and
    // the top cell carried along as in the ν = 0 case: length H − h).
    CHECK(record == Approx(base).epsilon(0.03));
    CHECK(base == Approx(expected).epsilon(0.03));
  } else {
    // A clamped face keeps the layer from expanding sideways: its σ_zz lies between the
    // uniaxial-stress value and the uniaxial-strain one, (1−ν)/((1+ν)(1−2ν)) = 2.14 times
    // higher (measured: 1.29 times the base reaction).
    CHECK(record > 1.1 * base);
    CHECK(record < (1 - nu) / ((1 + nu) * (1 - 2 * nu)) * base);
  }
}

TEST_CASE("A hold tag that no point of the body carries, or on a rigid body, is an input error", "[mpm][hold]") {
  const Real h = 1e-3;
  const PointSet points = held_column(h);
  Settings s;
  s.cell_size = h;
  BodySettings column = deformable("column", elastic(1e7, 0, 1000));
  BodySettings plate = rigid("plate", BodyRole::driven, Vec3(0, 0, -0.02), 1000);
  SECTION("unknown tag") {
    column.hold_tag = "bottom";
    CHECK_THROWS_WITH(Simulation(points, {column, plate}, s),
                      Catch::Contains("bodies.column.hold.tag") && Catch::Contains("'bottom'"));
  }
  SECTION("a tag carried only by another body's points") {
    plate.role = BodyRole::deformable;
    plate.material = elastic(1e7, 0, 1000);
    plate.hold_tag = "record";
    CHECK_THROWS_WITH(Simulation(points, {column, plate}, s), Catch::Contains("bodies.plate.hold.tag"));
  }
  SECTION("a rigid body") {
    plate.hold_tag = "record";
    CHECK_THROWS_WITH(Simulation(points, {column, plate}, s), Catch::Contains("only deformable bodies"));
  }
}
