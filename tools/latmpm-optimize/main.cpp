// latmpm-optimize: compliance topology optimisation on the static MPM solver, with LETO
// (paper C: carrier particles, multi-density quadrature points, narrow band, connectivity
// correction, MMA) and the SIMP baseline side by side. Thin: the scene is read, each method
// run and evaluated, and the results written by libs/optimize.
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <cstdio>
#include <filesystem>
#include <iostream>

#include "core/command_line.hpp"
#include "core/errors.hpp"
#include "core/file_transfer.hpp"
#include "core/provenance.hpp"
#include "core/tool_main.hpp"
#include "optimize/design_export.hpp"
#include "optimize/design_output.hpp"
#include "optimize/design_study.hpp"
#include "optimize/optimize_scene.hpp"

namespace {

const char* const manual =
    R"(latmpm-optimize: minimises the compliance of a part under a volume bound (paper C, LETO)
and, for comparison, with the SIMP baseline (density per cell, filter radius 1.5 cells,
Heaviside projection). Both solve the static equilibrium with the MPM static solver
(libs/statics, docs/statics.md) and step with NLopt's MMA.

The scene (TOML, docs/paper-c.md) gives the design domain (cell, size, planar), the material
(E, nu, SIMP penalty), supports (boxes of held grid nodes) and loads (a total force on the
points in a box), the volume bound and the methods; every dimensional value carries its unit.
--set overrides any key.

The output directory receives scene.toml (resolved), summary.toml (per method: iterations,
seconds per iteration, volume fraction and compliance of the binary design at the
optimisation resolution and on a grid refined twice; with one load, the exported part's
stiffness 2^mirrors F^2 / (2 C) from each compliance; the exported part's point volume),
and per method <method>-history.csv,
<method>-design.csv (x, y, z in mm, density, binary per quadrature point) and
<method>-design.gp (gnuplot draws <method>-design.png), and the binary design as
<method>-points.h5 (a point-set file for latmpm-solve: solid quadrature points, a planar
design extruded through its thickness, a half model mirrored through its symmetry plane
into the whole part) and <method>-part.stl (closed surface, mm: OpenVDB
level set of the solid voxels, meshed by volumeToMesh).

Exit status: 0 done, 1 usage, 2 bad scene (FILE:LINE: key: problem; nothing written),
3 numerical failure, 5 an output could not be written.

Sample runs (a small 2D cantilever, a few iterations of each method):
  $ latmpm-optimize $LATMPM_SOURCE_DIR/data/optimize/cantilever-2d.toml --set 'domain.size=["16mm","8mm","1mm"]' --set 'loads.tip.min=["15mm","-1mm","-1mm"]' --set 'loads.tip.max=["17mm","1mm","2mm"]' --set optimize.max_iterations=5 -o cantilever --quiet
  $ cat cantilever/summary.toml
  $ latmpm-optimize $LATMPM_SOURCE_DIR/data/optimize/cantilever-2d.toml --check
)";

int optimize_main(int argc, char** argv) {
  using namespace latmpm;
  using namespace latmpm::optimize;
  CommandLine cl("latmpm-optimize", manual);
  cl.positional("scene", "the optimisation scene (TOML, docs/paper-c.md)");
  cl.option("output", "DIR", "directory for the results (created if missing, files replaced)");
  cl.alias('o', "output");
  cl.repeated_option("set", "KEY=VALUE", "override a scene key, e.g. --set optimize.volume_fraction=0.4");
  cl.option("threads", "N", "threads, 0 = all cores", "0");
  cl.flag("quiet", "no progress lines on stderr");
  cl.flag("check", "read and check the scene, print it resolved, run nothing");
  cl.parse(argc, argv);
  if (!cl.given("output") && !cl.flag_set("check")) throw UsageError("missing -o DIR (or --check to only check the scene)");
  const long threads = cl.integer("threads");
  if (threads < 0) throw InputError("--threads", "", "must be 0 (all cores) or positive");

  // 1. The scene.
  const OptimizeScene scene = read_optimize_scene(cl.text("scene"), cl.all("set"));
  if (cl.flag_set("check")) {
    std::cout << scene.resolved_toml;
    return exit_ok;
  }
  Provenance provenance = Provenance::for_run("latmpm-optimize", argc, argv);
  provenance.inputs.push_back(scene.source);
  const std::vector<std::string> lines{provenance.summary_line(), "created " + provenance.created_utc};
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                            threads > 0 ? size_t(threads) : tbb::this_task_arena::max_concurrency());

  // 2. Each method: optimise, binarise, evaluate, write.
  const std::string dir = cl.text("output");
  std::filesystem::create_directories(dir);
  write_file_atomically(dir + "/scene.toml", scene.resolved_toml, "--output");
  std::vector<MethodOutcome> outcomes;
  std::vector<ExportReport> exports;
  for (const std::string& method : scene.methods) {
    auto progress = [&](const IterationRecord& r) {
      if (!cl.flag_set("quiet"))
        std::fprintf(stderr, "%s %4d  C %.6g J  v %.4f  t %.3f  points %zu  unknowns %zu  newton %d/%d  %.2f s\n",
                     method.c_str(), r.iteration, r.compliance, r.volume_fraction, r.threshold, r.active_points, r.unknowns,
                     r.newton_iterations, r.load_steps, r.seconds);
    };
    outcomes.push_back(run_method(scene, method, progress));
    const MethodOutcome& o = outcomes.back();
    write_method_files(dir, scene, o, lines);
    const ExportReport exported = export_design(scene.grid, o.binary, symmetry_planes(scene.grid, scene.load_case),
                                                dir + "/" + method + "-points.h5",
                                                dir + "/" + method + "-part.stl", provenance);
    exports.push_back(exported);
    std::printf("%s: %s %zu iterations (%s), %.3f s/iteration, volume %.2f %%, compliance %.6g J, refined %.6g J, "
                "%zu corrections; %zu points, %zu triangles (%s, enclosed %.4g mm^3, points %.4g mm^3)\n",
                cl.tool().c_str(), method.c_str(), o.result.history.size(), o.result.converged ? "converged" : "not converged",
                o.seconds_per_iteration, 100 * o.volume_fraction, o.compliance_binary, o.compliance_refined, o.corrections, exported.points,
                exported.triangles, exported.closed ? "closed" : "NOT closed", 1e9 * exported.surface_volume, 1e9 * exported.solid_volume);
  }
  write_summary(dir, scene, outcomes, exports, lines);
  return exit_ok;
}

}  // namespace

int main(int argc, char** argv) { return latmpm::run_tool("latmpm-optimize", argc, argv, optimize_main); }
