#include <catch2/catch.hpp>

#include <filesystem>

#include "core/errors.hpp"
#include "core/hdf5_file.hpp"
#include "geometry/strut_graph.hpp"
#include "scratch_dir.hpp"

using namespace latmpm;

TEST_CASE("A strut graph written to HDF5 reads back exactly", "[formats][geometry]") {
  StrutGraph g;
  g.name = "test";
  g.nodes = {{0, 0, 0}, {0.001, 0.002, 0.003}, {1.0 / 3.0, -2e-9, 5}};
  g.struts = {{0, 1, 0.0008}, {1, 2, 0.0012}};
  g.plates = {{"bottom_plate", {-1, -1, -0.003}, {1, 1, 0}}};
  g.parameters = {{"cell", "tetrahedral"}, {"strut_length", "0.008 m"}};
  const test::ScratchDir scratch("strut-graph-file");
  const std::string path = scratch / "sg.h5";
  {
    Hdf5File f(path, Hdf5File::Mode::create);
    write_strut_graph(f, g);
  }
  Hdf5File f(path, Hdf5File::Mode::read);
  REQUIRE(holds_strut_graph(f));
  StrutGraph back = read_strut_graph(f);
  CHECK(back.name == g.name);
  CHECK(back.strut_body == "lattice");
  REQUIRE(back.nodes.size() == g.nodes.size());
  for (size_t i = 0; i < g.nodes.size(); ++i) CHECK(back.nodes[i] == g.nodes[i]);
  REQUIRE(back.struts.size() == 2);
  CHECK(back.struts[1].a == 1);
  CHECK(back.struts[1].b == 2);
  CHECK(back.struts[1].radius == 0.0012);
  REQUIRE(back.plates.size() == 1);
  CHECK(back.plates[0].name == "bottom_plate");
  CHECK(back.plates[0].min == g.plates[0].min);
  CHECK(back.plates[0].max == g.plates[0].max);
  CHECK(back.parameters == g.parameters);
}

TEST_CASE("A strut naming a missing node is refused with the dataset named", "[formats][geometry]") {
  StrutGraph g;
  g.nodes = {{0, 0, 0}};
  g.struts = {{0, 5, 0.001}};
  const test::ScratchDir scratch("strut-graph-file");
  const std::string path = scratch / "sg-bad.h5";
  {
    Hdf5File f(path, Hdf5File::Mode::create);
    write_strut_graph(f, g);
  }
  Hdf5File f(path, Hdf5File::Mode::read);
  CHECK_THROWS_WITH(read_strut_graph(f), Catch::Contains("/geometry/struts") &&
                                             Catch::Contains("node that does not exist"));
}
