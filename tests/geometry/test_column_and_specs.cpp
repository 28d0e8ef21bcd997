// The buckling column, the flat-end flag in the file, and refusal of bad specifications.
#include <catch2/catch.hpp>

#include <filesystem>

#include "core/errors.hpp"
#include "core/hdf5_file.hpp"
#include "geometry/column.hpp"
#include "geometry/lattice.hpp"
#include "geometry/plates.hpp"
#include "scratch_dir.hpp"

using namespace latmpm;

TEST_CASE("The column is a flat-ended cylinder exactly L long between optional end plates",
          "[geometry][column]") {
  ColumnSpec spec{2.4e-3, 16e-3, 0, 0};
  spec.end_plate_thickness = GENERATE(0.0, 1e-3);
  const StrutGraph g = build_column(spec);
  CHECK(g.strut_ends == StrutEnds::flat);
  CHECK(g.strut_body == "column");
  const Eigen::AlignedBox3d column = solid_bounds(g, true);
  CHECK(column.sizes().z() == Approx(16e-3).epsilon(1e-12));
  CHECK(column.sizes().x() == Approx(2.4e-3).epsilon(1e-12));
  CHECK(column.min().z() == Approx(spec.end_plate_thickness).margin(1e-15));
  CHECK(g.plates.size() == (spec.end_plate_thickness > 0 ? 2u : 0u));
  if (!g.plates.empty()) CHECK(solid_bounds(g).sizes().z() == Approx(18e-3));
}

TEST_CASE("Flat strut ends survive the HDF5 round trip; old files read as round", "[geometry][formats]") {
  const test::ScratchDir scratch("column-ends");
  const std::string path = scratch / "column-ends.h5";
  const StrutGraph column = build_column({1.6e-3, 16e-3, 0, 0});
  {
    Hdf5File f(path, Hdf5File::Mode::create);
    write_strut_graph(f, column);
  }
  {
    Hdf5File f(path, Hdf5File::Mode::read);
    CHECK(read_strut_graph(f).strut_ends == StrutEnds::flat);
  }
  {
    Hdf5File f(path, Hdf5File::Mode::create);
    StrutGraph lattice = column;
    lattice.strut_ends = StrutEnds::round;
    write_strut_graph(f, lattice);
  }
  Hdf5File f(path, Hdf5File::Mode::read);
  CHECK(read_strut_graph(f).strut_ends == StrutEnds::round);
  std::filesystem::remove(path);
}

TEST_CASE("Bad specifications are refused naming the option", "[geometry]") {
  using Mutation = std::function<void(LatticeSpec&)>;
  auto [mutate, option] = GENERATE(table<Mutation, std::string>({
      {[](LatticeSpec& s) { s.strut_length = 0; }, "--strut-length"},
      {[](LatticeSpec& s) { s.strut_length = -1e-3; }, "--strut-length"},
      {[](LatticeSpec& s) { s.strut_diameter = 0; }, "--strut-diameter"},
      {[](LatticeSpec& s) { s.strut_diameter = 9e-3; }, "--strut-diameter"},
      {[](LatticeSpec& s) { s.angle = 0; }, "--angle"},
      {[](LatticeSpec& s) { s.angle = M_PI / 2; }, "--angle"},
      {[](LatticeSpec& s) { s.angle = -0.1; }, "--angle"},
      {[](LatticeSpec& s) { s.cells[1] = 0; }, "--cells"},
      {[](LatticeSpec& s) { s.cell = "kagome"; }, "--cell"},
      {[](LatticeSpec& s) { s.cell = "bcc"; }, "--angle"},  // bcc takes no angle
      {[](LatticeSpec& s) { s.plate_thickness = -1e-3; }, "--plates"},
      {[](LatticeSpec& s) { s.plate_thickness = 0.7e-3; }, "--plates"},  // thinner than r = 0.8 mm
  }));
  LatticeSpec spec = preset_lattice("T1P40");
  mutate(spec);
  CHECK_THROWS_WITH(build_lattice(spec), Catch::StartsWith(option + ":"));
  CHECK_THROWS_WITH(preset_lattice("T3P30"), Catch::StartsWith("--preset:") && Catch::Contains("T1P20"));
  CHECK_THROWS_WITH(build_column({0, 16e-3, 0, 0}), Catch::StartsWith("--diameter:"));
  CHECK_THROWS_WITH(build_column({1e-3, -1, 0, 0}), Catch::StartsWith("--length:"));
}
