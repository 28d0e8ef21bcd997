// STEP export checked by reading the file back with OpenCASCADE: one fused solid whose exact
// volume matches the analytic value (column) and the level-set volume (lattice junctions).
#include <catch2/catch.hpp>

#include <filesystem>

#include "cad/step_export.hpp"
#include "geometry/column.hpp"
#include "geometry/lattice.hpp"
#include "levelset/level_set_mesh.hpp"
#include "levelset/strut_level_set.hpp"
#include "scratch_dir.hpp"

using namespace latmpm;

namespace {
std::string temp_step(const std::string& name) {
  return test::process_scratch("step-export") / (name + ".step");
}
}  // namespace

TEST_CASE("The column's STEP is one solid of exactly the cylinder and plate volumes", "[cad]") {
  const double d = 2.4e-3, L = 16e-3, t = 1e-3, margin = 0.3e-3;
  const std::string path = temp_step("column");
  const StepReport written = write_step(build_column({d, L, t, margin}), path);
  CHECK(written.solids == 3);  // cylinder + two plates, flat ends: no spheres
  const StepContents read = read_step_contents(path);
  std::filesystem::remove(path);
  CHECK(read.solids == 1);
  const double side = d + 2 * margin;
  CHECK(read.volume == Approx(M_PI * d * d / 4 * L + 2 * side * side * t).epsilon(1e-6));
}

TEST_CASE("A lattice's STEP is one solid whose volume the level set reproduces", "[cad]") {
  LatticeSpec spec = preset_lattice("T1P30");
  spec.cells = {2, 1, 2};
  spec.plate_thickness = 1e-3;
  const StrutGraph graph = build_lattice(spec);
  const std::string path = temp_step("lattice");
  write_step(graph, path);
  const StepContents read = read_step_contents(path);
  std::filesystem::remove(path);
  CHECK(read.solids == 1);  // struts and plates fused into one connected body
  // Level-set volume at r/8: +0.44 % on a single capsule (tests/levelset), the creases at
  // the junctions pull the other way (measured −0.17 % here); allow 1 %.
  const double level_set = level_set_volume(*strut_graph_level_set(graph, spec.strut_diameter / 16));
  CHECK(level_set == Approx(read.volume).epsilon(0.01));
}
