// RUN_DIR/status.toml: how a latmpm-solve run ended, in one small file that pipelines and
// latmpm-post read instead of scraping log.txt (docs/scene.md, "The run directory").
// Written atomically (temporary file, then rename) at the start of a run ("running") and
// again when it ends, whatever the end: finished, stopped by run.max_steps, a numerical
// failure, bad input in a directory that exists, an interruption. A run killed outright
// (SIGKILL, power) leaves "running". Keys (units in the names):
//   status = "finished"      finished | max_steps | failed | bad_input | interrupted | error | running
//   exit = 0                 the process's exit status (README: 0 done, 2 bad input, 3 numerical
//                            failure, 4 internal; -1 while running)
//   reason = "..."           why it stopped ("" when it finished)
//   steps, simulated_time_s, points
//   wall_s, cpu_s            the whole process, summed over the parts of a resumed run
//   stepping_wall_s          the stepping loop alone (summed likewise)
//   updates_per_s            points × steps of this part / its stepping wall time
//   peak_memory_mb           this part's peak resident memory
//   tool, version, command, written_utc   provenance
//   precision = "double"     the solver build's particle precision (double | mixed, mpm/real.hpp)
//   cpu_model, cpus, vector_isa   the machine of this part (core/machine.hpp): the processor's
//                            name, the processors the process may use, and the vector instruction
//                            set the build targets; a cost is comparable only on the same ones
#pragma once
#include <cstdint>
#include <string>

#include "core/provenance.hpp"

namespace latmpm {

struct RunOutcome {
  std::string status = "running";
  int exit_status = -1;
  std::string reason;
  int64_t steps = 0;
  double simulated_time = 0;        // s
  size_t points = 0;
  double wall_seconds = 0;          // process, all parts
  double cpu_seconds = 0;           // user + system, all parts
  double stepping_wall_seconds = 0; // all parts
  double updates_per_second = 0;    // this part
  double peak_memory_mb = 0;        // this part
  std::string precision;            // the solver build's particle precision; "" when unknown
};

// The process's own measures so far (getrusage): CPU seconds (user + system), peak resident
// memory in MB, and wall seconds since the process started.
double process_cpu_seconds();
double process_peak_memory_mb();
double process_wall_seconds();

// A status that knows only why the run ended: the process's measures filled in, as for bad
// input found before the run started (exit 2) or an interruption (hostile's signal handling
// passes "interrupted by SIGTERM").
RunOutcome outcome_without_run(const std::string& status, int exit_status, const std::string& reason);

// Writes RUN_DIR/status.toml atomically. Throws InputError when it cannot.
void write_run_status(const std::string& run_dir, const RunOutcome& outcome, const Provenance& provenance);

}  // namespace latmpm
