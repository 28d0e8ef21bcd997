// latmpm-solve: runs a simulation scene (TOML) with the explicit MPM solver and writes the
// run directory. Thin: the scene is read by libs/scene, the run and its outputs live in
// libs/run_output (solve_run.hpp), the solver in libs/mpm.
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "core/command_line.hpp"
#include "core/errors.hpp"
#include "core/interruption.hpp"
#include "core/provenance.hpp"
#include "core/tool_main.hpp"
#include "run_output/run_status.hpp"
#include "run_output/solve_run.hpp"
#include "scene/scene.hpp"
#include "static_run/static_solve_run.hpp"
#ifdef LATMPM_WITH_MPI
#include "mpm/mpi_domain.hpp"
#endif

namespace {

const char* const manual =
    R"(latmpm-solve: runs a simulation scene with the explicit material point method.

The scene (TOML, docs/scene.md) names the point files (latmpm-voxelize), gives each body a
role (deformable, fixed, driven at a velocity) and a material, rigid bodies by geometry
(a driven plate, a fixed base, or a free flyer with a mass: [rigid_bodies]), the grid cell, shape function
(uGIMP, DDMP, ...), update scheme, time-step rule, end condition and outputs; every
dimensional value carries its unit ("0.4mm", "10MPa", "-100mm/s"). --set overrides any key.
The run directory receives scene.toml (resolved), log.txt, series.csv and series.h5 (time,
plate displacement, loads on the driven plate, the fixed base, the record layer and the
flyer, flyer speed and energy, energies and the energy balance), particle snapshots
(snapshots/*.h5 + snapshots.xmf, open it in ParaView) and checkpoint.h5.

Checkpoints: the run saves RUN_DIR/checkpoint.h5 every [checkpoint] every_steps steps or
every_minutes minutes (default 10 minutes) and when run.max_steps stops it;
`latmpm-solve --resume RUN_DIR` continues from it with RUN_DIR/scene.toml and appends to the
series and snapshots, with the same results as a run that never stopped (--set may change
run.max_steps, run.end, output and checkpoint keys for the rest of the run).

Stopping: SIGINT (Ctrl-C), SIGTERM or SIGHUP end the run after the current step with the
checkpoint, series and a snapshot saved; --resume continues it exactly. A second signal ends
it at once (the last periodic checkpoint is kept).

The run directory also receives status.toml, written atomically at the start ("running") and
at the end of every run, a failed one too, and when bad input stops a run whose directory
exists: status, exit status, reason, steps, simulated time, wall and CPU seconds, particle-
updates per second, points and peak memory. Pipelines read it, not the log.

`latmpm-solve --list shapes` (schemes, materials, boundaries) prints what a scene can choose,
one name a line: ask the tool, not the docs.

Exit status: 0 done, 1 usage, 2 bad scene or points (FILE:LINE: key: problem; nothing
written), 3 numerical failure (the log says why; series and snapshots so far are kept),
5 an output could not be written (disk full), 128+N stopped by signal N (130 Ctrl-C, 143
SIGTERM) with the checkpoint saved (docs/robustness.md).

Sample runs (a 16 mm column, 1.6 mm thick, compressed by 1 mm on a coarse 0.8 mm grid):
  $ latmpm-lattice --column --diameter 1.6mm --length 16mm --end-plates 0.8mm -o c.h5
  $ latmpm-voxelize c.h5 --cell 0.8mm --ppc 2 -o c-points.h5
  $ latmpm-solve $LATMPM_SOURCE_DIR/data/scenes/column-tiny.toml --set points.0.file=c-points.h5 -o run --quiet
  $ cat run/status.toml
  $ latmpm-solve --list shapes
  $ head -3 run/series.csv
  $ latmpm-solve $LATMPM_SOURCE_DIR/data/scenes/column-tiny.toml --set points.0.file=c-points.h5 --set grid.shape=linear --check
  $ latmpm-solve $LATMPM_SOURCE_DIR/data/scenes/column-tiny.toml --set points.0.file=c-points.h5 --set run.max_steps=100 -o half --quiet
  $ latmpm-solve --resume half --set run.max_steps=0 --quiet
  $ latmpm-solve $LATMPM_SOURCE_DIR/data/scenes/column-platen-contact.toml --set points.0.file=c-points.h5 --set run.max_steps=300 -o platen --quiet
  $ latmpm-solve $LATMPM_SOURCE_DIR/data/scenes/column-tiny.toml --set points.0.file=c-points.h5 --set solver.kind=static --set solver.increments=4 -o static --quiet

With [solver] kind = "static" (docs/statics.md) the driven body is moved to
run.end.plate_displacement in solver.increments equilibrium steps (projected Newton on the
MPM grid, paper C Sec. 3.3); series and snapshots hold one row and one frame per increment,
and the run reports where the static path ends (buckling) if it does.
)";

int solve(int argc, char** argv) {
  using namespace latmpm;
  CommandLine cl("latmpm-solve", manual);
  cl.positional("scene", "the scene file (TOML, docs/scene.md); not with --resume", false);
  cl.option("resume", "RUN_DIR", "continue the run in RUN_DIR from its checkpoint.h5 (its scene.toml is the scene)");
  cl.option("output", "RUN_DIR", "directory for the run's files (created if missing, files replaced)");
  cl.alias('o', "output");
  cl.repeated_option("set", "KEY=VALUE", "override a scene key, e.g. --set grid.cell=0.4mm, --set points.0.file=p.h5");
  cl.option("threads", "N", "solver threads, 0 = all cores", "0");
  cl.flag("quiet", "no progress lines on stderr");
  cl.option("list", "CHOICE", "print what a scene can choose, one a line, and exit: shapes, schemes, materials, boundaries");
  cl.flag("check", "read and check the scene, its points and the solver set-up, print the resolved scene, run nothing");
  cl.parse(argc, argv);
  if (cl.given("list")) {
    const auto names = scene_choice_names(cl.text("list"));
    if (names.empty())
      throw InputError("--list", "", "'" + cl.text("list") + "' is not one of shapes, schemes, materials, boundaries");
    for (const auto& name : names) std::cout << name << "\n";
    return exit_ok;
  }
  const bool resume = cl.given("resume");
  if (resume && (cl.given("scene") || cl.given("output")))
    throw UsageError("--resume RUN_DIR takes the scene and the output directory from RUN_DIR: give no scene and no -o");
  if (!resume && !cl.given("scene")) throw UsageError("missing the scene file (or --resume RUN_DIR)");
  if (!resume && !cl.given("output") && !cl.flag_set("check"))
    throw UsageError("missing -o RUN_DIR (or --check to only check the scene)");
  const std::string run_dir = resume ? cl.text("resume") : (cl.given("output") ? cl.text("output") : "");
  const long threads = cl.integer("threads");
  if (threads < 0) throw InputError("--threads", "", "must be 0 (all cores) or positive");

  Provenance provenance = Provenance::for_run("latmpm-solve", argc, argv);
  SolveSummary s;
  try {
    // 1. The scene, with the command line's overrides.
    Scene scene = read_scene(resume ? run_dir + "/scene.toml" : cl.text("scene"), cl.all("set"));

    // 2. Points and solver: every input error is found here, before anything is written.
    provenance.inputs.push_back(scene.source);
    if (scene.solver.kind == SolverSpec::static_equilibrium && !cl.flag_set("check")) {
      if (resume) throw UsageError("--resume: a static solve has no checkpoint; run it again");
      const StaticSolveSummary st = run_static_scene(scene, provenance, run_dir, !cl.flag_set("quiet"));
      if (st.signal) {
        std::fprintf(stderr, "%s: stopped by %s after %d increments (travel %.6g m); the series holds them -> %s\n",
                     cl.tool().c_str(), signal_name(st.signal), st.increments, st.travel, run_dir.c_str());
        return exit_signal_base + st.signal;
      }
      std::printf("%s: static %s, %d increments, travel %.6g m, %zu points, %zu unknowns, wall %.2f s -> %s\n",
                  cl.tool().c_str(), st.status.c_str(), st.increments, st.travel, st.points, st.unknowns,
                  st.wall_seconds, run_dir.c_str());
      if (st.end_travel > 0)
        std::printf("%s: the static path ends at travel %.6g m, load %.6g N\n", cl.tool().c_str(), st.end_travel,
                    st.end_load);
      return exit_ok;
    }
    SolveOptions options;
    options.threads = int(threads);
    options.progress = !cl.flag_set("quiet");
    options.resume = resume;
    SolveRun run(scene, provenance, options);
    if (cl.flag_set("check")) {
      std::cout << scene.resolved_toml;
      return exit_ok;
    }

    // 3. The run.
    s = run.run(run_dir);
    if (!run.writes_output()) return exit_ok;  // rank 0 reports
  } catch (const InputError& e) {
    // Nothing else is written on bad input; a run directory that exists says why its run
    // did not happen (a pipeline reads status.toml, not stderr).
    if (!run_dir.empty() && !cl.flag_set("check") && std::filesystem::is_directory(run_dir))
      write_run_status(run_dir, outcome_without_run("bad_input", exit_bad_input, e.what()), provenance);
    throw;
  }
  if (s.signal) {
    std::fprintf(stderr, "%s: stopped by %s at step %lld, checkpoint saved: latmpm-solve --resume %s continues\n",
                 cl.tool().c_str(), signal_name(s.signal), static_cast<long long>(s.steps), run_dir.c_str());
    return exit_signal_base + s.signal;
  }
  std::printf("%s: %s, %lld steps, t = %.6g s, wall %.2f s, %.3g particle-updates/s, %zu particles -> %s\n",
              cl.tool().c_str(), s.status.c_str(), static_cast<long long>(s.steps), s.simulated_time,
              s.wall_seconds, s.updates_per_second, s.particles, run_dir.c_str());
  return exit_ok;
}

}  // namespace

int main(int argc, char** argv) {
#ifdef LATMPM_WITH_MPI
  // `mpirun -np N latmpm-solve ...` (docs/cluster.md); a non-zero status stops every process.
  latmpm::mpm::MpiSession mpi(argc, argv);
  return mpi.finish(latmpm::run_tool("latmpm-solve", argc, argv, solve));
#else
  return latmpm::run_tool("latmpm-solve", argc, argv, solve);
#endif
}
