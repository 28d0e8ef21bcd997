#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <numeric>

#include "core/errors.hpp"
#include "core/hdf5_file.hpp"
#include "core/provenance.hpp"
#include "points/point_set.hpp"
#include "scene/scene_points.hpp"
#include "scratch_dir.hpp"

using namespace latmpm;
namespace fs = std::filesystem;

namespace {

// `n` points per body on a line, volumes 1, 2, 3... × 1e-9 m³ so sums identify files.
PointSet line_of_points(const std::vector<std::string>& bodies, int n, double first_volume) {
  PointSet p;
  p.body_names = bodies;
  for (size_t b = 0; b < bodies.size(); ++b)
    for (int i = 0; i < n; ++i) {
      p.position.emplace_back(i * 1e-3, double(b) * 1e-3, 0);
      p.volume.push_back((first_volume + double(p.volume.size())) * 1e-9);
      p.body.push_back(int32_t(b));
      p.half_size.emplace_back(5e-4, 5e-4, 5e-4);
    }
  p.tags["record"].assign(p.size(), 0);
  p.tags["record"][0] = 1;
  p.cell_size = 1e-3;
  p.ppc = 1;
  return p;
}

std::string write(const PointSet& p, const std::string& name) {
  std::string path = test::process_scratch("scene-points") / name;
  Hdf5File f(path, Hdf5File::Mode::create);
  write_point_set(f, p);
  write_provenance(f, Provenance{"latmpm-test", "0", "make " + name, {}, "2024-01-01T00:00:00Z", {}});
  return path;
}

Scene scene_with(const std::vector<std::string>& bodies, const std::vector<std::string>& files) {
  Scene s;
  for (size_t i = 0; i < files.size(); ++i) s.point_files.push_back({files[i], "scene.toml:" + std::to_string(10 + i)});
  for (size_t i = 0; i < bodies.size(); ++i) {
    BodySpec b;
    b.name = bodies[i];
    b.where = "scene.toml:" + std::to_string(20 + i);
    s.bodies.push_back(b);
  }
  return s;
}

double total_volume(const PointSet& p, int body) {
  double v = 0;
  for (size_t i = 0; i < p.size(); ++i)
    if (p.body[i] == body) v += p.volume[i];
  return v;
}

}  // namespace

TEST_CASE("Point files merge into one set whose bodies follow the scene's order", "[scene]") {
  PointSet a = line_of_points({"column", "bottom_plate"}, 4, 1);
  PointSet b = line_of_points({"top_plate"}, 3, 100);
  b.tags.clear();
  b.tags["top_layer"].assign(b.size(), 1);
  std::string fa = write(a, "a.h5"), fb = write(b, "b.h5");
  Scene s = scene_with({"top_plate", "column", "bottom_plate"}, {fa, fb});

  Provenance prov;
  PointSet all = load_scene_points(s, &prov);
  REQUIRE(all.size() == a.size() + b.size());
  CHECK(all.body_names == std::vector<std::string>{"top_plate", "column", "bottom_plate"});
  // Volumes per body are conserved through the renumbering.
  CHECK(total_volume(all, 0) == Approx(total_volume(b, 0)));
  CHECK(total_volume(all, 1) == Approx(total_volume(a, 0)));
  CHECK(total_volume(all, 2) == Approx(total_volume(a, 1)));
  // Tags from either file cover every point, 0 where a file lacks them.
  REQUIRE(all.tags.at("record").size() == all.size());
  REQUIRE(all.tags.at("top_layer").size() == all.size());
  auto count = [](const std::vector<uint8_t>& m) { return std::accumulate(m.begin(), m.end(), 0); };
  CHECK(count(all.tags.at("record")) == 1);
  CHECK(count(all.tags.at("top_layer")) == int(b.size()));
  CHECK(all.cell_size == a.cell_size);
  CHECK_NOTHROW(all.validate("merged"));
  // Provenance: both inputs, and each file's own run in the history.
  CHECK(prov.inputs == std::vector<std::string>{fa, fb});
  REQUIRE(prov.history.size() == 2);
  CHECK_THAT(prov.history[0], Catch::Contains("make a.h5"));
}

TEST_CASE("A body in a point file that the scene does not describe is an error at the file's line", "[scene]") {
  std::string fa = write(line_of_points({"column", "bottom_plate"}, 2, 1), "c.h5");
  Scene s = scene_with({"column"}, {fa});
  try {
    load_scene_points(s);
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.where() == "scene.toml:10");
    CHECK(e.field() == "points.0.file");
    CHECK_THAT(e.problem(), Catch::Contains("bottom_plate") && Catch::Contains("[bodies.bottom_plate]"));
  }
}

TEST_CASE("A described body that no point file holds is an error at the body's line", "[scene]") {
  std::string fa = write(line_of_points({"column"}, 2, 1), "d.h5");
  Scene s = scene_with({"column", "flyer"}, {fa});
  try {
    load_scene_points(s);
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.where() == "scene.toml:21");
    CHECK(e.field() == "bodies.flyer");
    CHECK_THAT(e.problem(), Catch::Contains("column"));
  }
}

TEST_CASE("An omitted body's points are dropped with their tags, the others keep theirs", "[scene]") {
  PointSet a = line_of_points({"bottom_plate", "lattice", "top_plate"}, 4, 1);
  a.tags["record"][0] = 1;  // the bottom plate's first point, dropped with it
  a.tags["top_layer"].assign(a.size(), 0);
  for (size_t p = 8; p < 12; ++p) a.tags["top_layer"][p] = 1;  // the top plate's points
  a.tags["top_layer"][4] = 1;                                    // and one lattice point
  std::string fa = write(a, "omit.h5");
  Scene s = scene_with({"lattice"}, {fa});
  for (const char* name : {"bottom_plate", "top_plate"}) {
    BodySpec b;
    b.name = name;
    b.where = "scene.toml:30";
    s.omitted_bodies.push_back(b);
  }
  PointSet all = load_scene_points(s);
  REQUIRE(all.size() == 4);
  CHECK(all.body_names == std::vector<std::string>{"lattice"});
  CHECK(total_volume(all, 0) == Approx(total_volume(a, 1)));
  auto count = [](const std::vector<uint8_t>& m) { return std::accumulate(m.begin(), m.end(), 0); };
  REQUIRE(all.tags.at("record").size() == 4);
  CHECK(count(all.tags.at("record")) == 0);
  CHECK(count(all.tags.at("top_layer")) == 1);
  CHECK(all.tags.at("top_layer")[0] == 1);
  CHECK_NOTHROW(all.validate("omitted"));
}

TEST_CASE("An omitted body that no point file holds is an error at its line", "[scene]") {
  std::string fa = write(line_of_points({"lattice"}, 2, 1), "omit-missing.h5");
  Scene s = scene_with({"lattice"}, {fa});
  BodySpec plate;
  plate.name = "top_plat";
  plate.where = "scene.toml:31";
  s.omitted_bodies.push_back(plate);
  try {
    load_scene_points(s);
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.where() == "scene.toml:31");
    CHECK(e.field() == "bodies.top_plat");
    CHECK_THAT(e.problem(), Catch::Contains("lattice"));
  }
}
