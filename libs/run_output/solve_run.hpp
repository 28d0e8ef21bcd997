// One latmpm-solve run, in the skeleton of a deal.II tutorial: set up, then run with output.
//   SolveRun run(scene, provenance, options);  // reads points, builds the solver: every
//                                              // InputError happens here, nothing written
//   SolveSummary s = run.run("results/run1");   // writes RUN_DIR as it goes
// RUN_DIR (created if missing; files of an earlier run replaced):
//   scene.toml      the resolved scene (defaults filled in, paths absolute)
//   log.txt         command, version, settings, progress lines, how the run ended
//   series.csv/.h5  one row every output.series_every steps (solver_series.hpp)
//   snapshots/snap_<step>.h5 + snapshots.xmf   particles for ParaView
//   checkpoint.h5   the whole solver state every checkpoint.every_steps steps / every_minutes
//                   minutes and when run.max_steps stops the run (atomically replaced);
//                   SolveOptions::resume continues from it with the same results
// SIGINT, SIGTERM or SIGHUP (core/interruption.hpp): the run finishes the step it is in, saves
// the checkpoint, the series and a snapshot, and returns with status "interrupted" and the
// signal; --resume continues it as if it had never stopped. A second signal ends it at once.
// On NumericalError (Stability): the log says why, the series is saved, the state at the
// failure is snapshotted, then the error is rethrown (exit status 3).
#pragma once
#include <memory>
#include <string>

#include "core/provenance.hpp"
#include "scene/scene.hpp"

namespace latmpm {

namespace mpm {
class Simulation;
}

struct SolveOptions {
  int threads = 0;       // solver threads, 0 = all
  bool progress = true;  // progress lines on stderr
  double log_interval_s = 10;  // seconds between progress lines in log.txt
  // Continue the run in RUN_DIR from RUN_DIR/checkpoint.h5 (latmpm-solve --resume): the
  // series and snapshots up to the checkpoint are kept and appended to, the log continues.
  bool resume = false;
};

struct SolveSummary {
  std::string status;  // "finished", "max_steps" or "interrupted"
  int signal = 0;      // the signal that interrupted the run
  int64_t steps = 0;
  double simulated_time = 0;        // s
  double wall_seconds = 0;          // the stepping loop, outputs included
  double updates_per_second = 0;    // particles × steps / wall_seconds
  size_t particles = 0;
};

class SolveRun {
 public:
  SolveRun(Scene scene, Provenance provenance, const SolveOptions& options);
  ~SolveRun();
  SolveSummary run(const std::string& run_dir);
  const mpm::Simulation& simulation() const { return *simulation_; }
  // False on the MPI processes other than rank 0, which write nothing (docs/cluster.md).
  bool writes_output() const;

 private:
  Scene scene_;
  Provenance provenance_;
  SolveOptions options_;
  std::unique_ptr<mpm::Simulation> simulation_;
  double specimen_area_ = 0;  // m², A0 of load_average, from the starting state (not a checkpoint's)
  std::string points_summary_;
};

}  // namespace latmpm
