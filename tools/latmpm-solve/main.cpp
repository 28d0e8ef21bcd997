// latmpm-solve: runs a simulation scene (TOML) with the explicit MPM solver and writes the
// run directory. Thin: the scene is read by libs/scene, the run and its outputs live in
// libs/run_output (solve_run.hpp), the solver in libs/mpm.
#include <cstdio>
#include <iostream>

#include "core/command_line.hpp"
#include "core/errors.hpp"
#include "core/provenance.hpp"
#include "core/tool_main.hpp"
#include "run_output/solve_run.hpp"
#include "scene/scene.hpp"

namespace {

const char* const manual =
    R"(latmpm-solve: runs a simulation scene with the explicit material point method.

The scene (TOML, docs/scene.md) names the point files (latmpm-voxelize), gives each body a
role (deformable, fixed, driven at a velocity) and a material, the grid cell, shape
function, update scheme, time-step rule, end condition and outputs; every dimensional value
carries its unit ("0.4mm", "10MPa", "-100mm/s"). --set overrides any key. The run directory
receives scene.toml (resolved), log.txt, series.csv and series.h5 (time, plate displacement,
loads on the driven plate, the fixed base and the record layer, energies), and particle
snapshots (snapshots/*.h5 + snapshots.xmf, open it in ParaView).

Exit status: 0 done, 1 usage, 2 bad scene or points (FILE:LINE: key: problem; nothing
written), 3 numerical failure (the log says why; series and snapshots so far are kept).

Sample runs (a 16 mm column, 1.6 mm thick, compressed by 1 mm on a coarse 0.8 mm grid):
  $ latmpm-lattice --column --diameter 1.6mm --length 16mm --end-plates 0.8mm -o c.h5
  $ latmpm-voxelize c.h5 --cell 0.8mm --ppc 2 -o c-points.h5
  $ latmpm-solve $LATMPM_SOURCE_DIR/data/scenes/column-tiny.toml --set points.0.file=c-points.h5 -o run --quiet
  $ head -3 run/series.csv
  $ latmpm-solve $LATMPM_SOURCE_DIR/data/scenes/column-tiny.toml --set points.0.file=c-points.h5 --set grid.shape=linear --check
)";

int solve(int argc, char** argv) {
  using namespace latmpm;
  CommandLine cl("latmpm-solve", manual);
  cl.positional("scene", "the scene file (TOML, docs/scene.md)");
  cl.option("output", "RUN_DIR", "directory for the run's files (created if missing, files replaced)");
  cl.alias('o', "output");
  cl.repeated_option("set", "KEY=VALUE", "override a scene key, e.g. --set grid.cell=0.4mm, --set points.0.file=p.h5");
  cl.option("threads", "N", "solver threads, 0 = all cores", "0");
  cl.flag("quiet", "no progress lines on stderr");
  cl.flag("check", "read and check the scene, its points and the solver set-up, print the resolved scene, run nothing");
  cl.parse(argc, argv);
  if (!cl.given("output") && !cl.flag_set("check"))
    throw UsageError("missing -o RUN_DIR (or --check to only check the scene)");
  const long threads = cl.integer("threads");
  if (threads < 0) throw InputError("--threads", "", "must be 0 (all cores) or positive");

  // 1. The scene, with the command line's overrides.
  Scene scene = read_scene(cl.text("scene"), cl.all("set"));

  // 2. Points and solver: every input error is found here, before anything is written.
  Provenance provenance = Provenance::for_run("latmpm-solve", argc, argv);
  provenance.inputs.push_back(scene.source);
  SolveOptions options;
  options.threads = int(threads);
  options.progress = !cl.flag_set("quiet");
  SolveRun run(scene, provenance, options);
  if (cl.flag_set("check")) {
    std::cout << scene.resolved_toml;
    return exit_ok;
  }

  // 3. The run.
  SolveSummary s = run.run(cl.text("output"));
  std::printf("%s: %s, %lld steps, t = %.6g s, wall %.2f s, %.3g particle-updates/s, %zu particles -> %s\n",
              cl.tool().c_str(), s.status.c_str(), static_cast<long long>(s.steps), s.simulated_time,
              s.wall_seconds, s.updates_per_second, s.particles, cl.text("output").c_str());
  return exit_ok;
}

}  // namespace

int main(int argc, char** argv) { return latmpm::run_tool("latmpm-solve", argc, argv, solve); }
