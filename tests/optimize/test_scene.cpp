// latmpm-optimize's scene: a valid scene reads with its defaults resolved, and bad input is
// refused with one InputError naming the file, the key and the problem (issue 19: a volume
// bound outside (0, 1), a load on no material, an empty design domain; also a unit missing
// and an unknown key).
#include <catch2/catch.hpp>

#include <string>

#include "core/errors.hpp"
#include "optimize/optimize_scene.hpp"

using namespace latmpm;
using namespace latmpm::optimize;

namespace {
const std::string scene = R"(
[domain]
cell = "1mm"
size = ["8mm", "4mm", "1mm"]
planar = true
[material]
E = "1GPa"
nu = 0.3
[supports.clamp]
min = ["-1mm", "-1mm", "-1mm"]
max = ["0mm", "10mm", "2mm"]
[loads.tip]
min = ["7mm", "-1mm", "-1mm"]
max = ["9mm", "1mm", "2mm"]
force = ["0N", "-1N", "0N"]
[optimize]
volume_fraction = 0.3
)";

std::string error_of(const std::vector<std::string>& overrides) {
  try {
    parse_optimize_scene(scene, "s.toml", overrides);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE("A valid optimisation scene reads with its defaults", "[optimize]") {
  const OptimizeScene s = parse_optimize_scene(scene, "s.toml");
  CHECK(s.grid.cells == Index3(8, 4, 1));
  CHECK(s.grid.planar);
  CHECK(s.grid.thickness == Approx(1e-3));
  CHECK(s.material.young_modulus == Approx(1e9));
  CHECK(s.methods == std::vector<std::string>{"leto", "simp"});
  CHECK(s.simp.filter_radius_cells == 1.5);
  CHECK(s.load_case.loads.at(0).force.y() == Approx(-1));
  CHECK(s.resolved_toml.find("band_end") != std::string::npos);
}

TEST_CASE("Bad optimisation scenes are refused with one line naming the key", "[optimize]") {
  using Case = std::pair<std::vector<std::string>, std::string>;
  const auto [overrides, expected] = GENERATE(
      Case{{"optimize.volume_fraction=1.2"}, "optimize.volume_fraction: must lie in (0, 1)"},
      Case{{"optimize.volume_fraction=0"}, "optimize.volume_fraction: must lie in (0, 1)"},
      Case{{"leto.volume_fraction=1"}, "leto.volume_fraction: must lie in (0, 1)"},
      Case{{"material.model=\"j2\""}, "material.model: expected linear_elastic or neo_hookean"},
      Case{{"leto.sharpen=0.5"}, "leto.sharpen: must be 0 (off)"},
      Case{{"loads.tip.min=[\"20mm\", \"20mm\", \"0mm\"]", "loads.tip.max=[\"21mm\", \"21mm\", \"1mm\"]"},
           "loads.tip.min: the load acts on no material"},
      Case{{"domain.size=[\"0mm\", \"4mm\", \"1mm\"]"}, "domain.size: the design domain is empty"},
      Case{{"domain.size=[\"8.5mm\", \"4mm\", \"1mm\"]"}, "domain.size: component 0 is not a whole number of cells"},
      Case{{"material.E=1e9"}, "material.E"},
      Case{{"optimize.volume_fracton=0.3"}, "volume_fracton"},
      Case{{"supports.clamp.min=[\"50mm\", \"50mm\", \"50mm\"]", "supports.clamp.max=[\"60mm\", \"60mm\", \"60mm\"]"},
           "the support holds no grid node"});
  const std::string message = error_of(overrides);
  CAPTURE(overrides, message);
  CHECK(message.find(expected) != std::string::npos);
  CHECK(message.find("--set") != std::string::npos);
  CHECK(message.find('\n') == std::string::npos);
}
