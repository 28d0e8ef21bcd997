#!/usr/bin/env bash
# One pipeline case: latmpm-solve with the scene and overrides of RUN_DIR.args (one word per
# line: the scene, then the solver's options), into RUN_DIR. The solver writes
# RUN_DIR/status.toml at the end of every run (how it ended, steps, wall and CPU time,
# particle-updates per second, points, peak memory). This script touches the stamp
# RUN_DIR/done only when the run ended as a pipeline wants it, so `make` reruns a failed or
# interrupted run.
# With ALLOW_FAILURE = 1, a numerical failure of the solver (exit status 3) is an outcome, not
# an error: the stamp is made (the trade-off records which settings fail).
# A run stopped part-way (RUN_DIR/checkpoint.h5, written every 10 minutes by long scenes)
# continues from its checkpoint (latmpm-solve --resume) when RUN_DIR.args is still the one it
# was started with (RUN_DIR/args.used: the same build of the solver too); the solver adds up
# wall and CPU time over the parts.
# A finished run under results/<experiment>/paper*/ is then recorded in records/ (record-run.sh).
# usage: solve-case.sh BIN_DIR RUN_DIR THREADS [ALLOW_FAILURE]
set -euo pipefail
bin=$1 run_dir=$2 threads=$3 allow_failure=${4:-0}
# The solver's arguments: RUN_DIR.args but its comment lines (the solver's version, which
# makes a run of another build stale: pipelines/common.mk).
mapfile -t args < <(grep -v '^#' "$run_dir.args")
rm -f "$run_dir/done"
# How the last run in RUN_DIR ended (status.toml's status; empty when there is none).
ended() { sed -n 's/^status = "\(.*\)"$/\1/p' "$run_dir/status.toml" 2>/dev/null; }
# Resumable: a checkpoint of a run that did not end (interrupted, killed, stopped by
# run.max_steps), the same arguments, and no file they name newer than the checkpoint.
resumable() {
  [ -f "$run_dir/checkpoint.h5" ] && cmp -s "$run_dir.args" "$run_dir/args.used" || return 1
  case $(ended) in finished | failed | error) return 1 ;; esac
  local word file
  for word in "${args[@]}"; do
    file=${word#*=}
    if [ -f "$file" ] && [ "$file" -nt "$run_dir/checkpoint.h5" ]; then return 1; fi
  done
}
if resumable; then
  echo "solve-case.sh: $run_dir continues from its checkpoint" >&2
  solve=("$bin/latmpm-solve" --resume "$run_dir")
else
  mkdir -p "$run_dir"
  cp "$run_dir.args" "$run_dir/args.used"
  solve=("$bin/latmpm-solve" "${args[@]}" -o "$run_dir")
fi
solve_status=0
"${solve[@]}" --threads "$threads" --quiet > "$run_dir/summary.txt" || solve_status=$?
if [ "$solve_status" -ne 0 ] && ! { [ "$solve_status" -eq 3 ] && [ "$allow_failure" = 1 ]; }; then
  exit "$solve_status"
fi
touch "$run_dir/done"
# A paper-resolution run is recorded in records/ (the run kept in the repository).
bash "$(dirname "$0")/record-run.sh" "$run_dir" || echo "solve-case.sh: $run_dir finished but was not recorded in records/" >&2
