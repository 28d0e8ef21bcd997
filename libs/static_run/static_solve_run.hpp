// One latmpm-solve run with [solver] kind = "static": the scene's platen is moved to
// run.end.plate_displacement in solver.increments equilibrium steps (libs/statics), and
// RUN_DIR receives what an explicit run writes, so latmpm-post and ParaView read it as is:
//   scene.toml, log.txt   the resolved scene; settings, per-increment Newton figures, the end
//   series.csv/.h5        one row per converged increment ("time" is the travel divided by
//                         the driven speed, so a static and an explicit curve share an axis)
//   snapshots/ + snapshots.xmf   the points at every increment (x = X + u(X), σ, J)
#pragma once
#include <string>

#include "core/provenance.hpp"
#include "scene/scene.hpp"

namespace latmpm {

struct StaticSolveSummary {
  std::string status;       // "finished", "unstable" (path ended), "not converged" or "interrupted"
  int signal = 0;           // the signal that stopped it ("interrupted"), else 0
  int increments = 0;       // converged equilibrium steps (bisection included)
  double travel = 0;        // m, the last converged travel
  double end_travel = 0;    // m, where the path ended (0 if it did not)
  double end_load = 0;      // N
  double wall_seconds = 0;
  size_t points = 0, unknowns = 0;
};

// Reads the points, builds the problem (InputErrors here, nothing written), runs and writes.
// SIGINT, SIGTERM or SIGHUP stop the path before the next Newton step (core/interruption.hpp):
// the converged increments stay in the series and snapshots, status.toml says "interrupted"
// (a static solve has no checkpoint: a new run starts again).
StaticSolveSummary run_static_scene(const Scene& scene, Provenance provenance, const std::string& run_dir,
                                    bool progress);

}  // namespace latmpm
