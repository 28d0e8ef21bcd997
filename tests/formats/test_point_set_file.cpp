#include <catch2/catch.hpp>

#include <filesystem>

#include "core/errors.hpp"
#include "core/hdf5_file.hpp"
#include "points/point_set.hpp"
#include "scratch_dir.hpp"

using namespace latmpm;

namespace {
PointSet sample() {
  PointSet p;
  p.position = {{0.1, 0.2, 0.3}, {1e-7, -2, 3.5}};
  p.volume = {1e-9, 2.5e-10};
  p.body = {0, 1};
  p.half_size = {{1e-4, 1e-4, 1e-4}, {2e-4, 2e-4, 1e-4}};
  p.body_names = {"lattice", "bottom_plate"};
  p.tags["record"] = {0, 1};
  p.cell_size = 0.00064;
  p.ppc = 2;
  p.parameters = {{"layer_height", "0.00933 m"}};
  return p;
}
}  // namespace

TEST_CASE("A point set written to HDF5 reads back exactly", "[formats][points]") {
  PointSet p = sample();
  const test::ScratchDir scratch("point-set-file");
  const std::string path = scratch / "ps.h5";
  {
    Hdf5File f(path, Hdf5File::Mode::create);
    write_point_set(f, p);
  }
  Hdf5File f(path, Hdf5File::Mode::read);
  PointSet back = read_point_set(f);
  CHECK(back.position == p.position);
  CHECK(back.volume == p.volume);
  CHECK(back.body == p.body);
  CHECK(back.half_size == p.half_size);
  CHECK(back.body_names == p.body_names);
  CHECK(back.tags == p.tags);
  CHECK(back.cell_size == p.cell_size);
  CHECK(back.ppc == p.ppc);
  CHECK(back.parameters == p.parameters);
}

TEST_CASE("Invalid point sets are refused naming the field", "[formats][points]") {
  PointSet p = sample();
  p.volume[1] = 0;
  CHECK_THROWS_WITH(p.validate("x.h5"), Catch::Contains("x.h5") && Catch::Contains("/points/volume"));
  p = sample();
  p.body[0] = 7;
  CHECK_THROWS_WITH(p.validate("x.h5"), Catch::Contains("/points/body"));
  p = sample();
  p.position[0].x() = std::nan("");
  CHECK_THROWS_WITH(p.validate("x.h5"), Catch::Contains("not finite"));
  p = sample();
  p.tags["record"].pop_back();
  CHECK_THROWS_WITH(p.validate("x.h5"), Catch::Contains("/points/tags/record"));
}
