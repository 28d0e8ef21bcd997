#!/usr/bin/env bash
# One pipeline case: latmpm-solve with the scene and overrides of RUN_DIR.args (one word per
# line: the scene, then the solver's options), into RUN_DIR. Writes RUN_DIR/wall_time.txt
# (wall_s, cpu_s, steps, points, updates_per_s) only when the solver finished, so the stamp
# of a failed or interrupted run never exists and `make` reruns it.
# With ALLOW_FAILURE = 1, a numerical failure of the solver (exit status 3) is an outcome, not
# an error: the stamp is written with status=failed and the log's reason (the trade-off
# records which settings fail).
# A run stopped part-way (RUN_DIR/checkpoint.h5, written every 10 minutes by long scenes)
# continues from its checkpoint (latmpm-solve --resume) when RUN_DIR.args is still the one it
# was started with (RUN_DIR/args.used); wall and CPU time then add up over the parts that
# /usr/bin/time saw (time-parts.txt: a part killed with its shell leaves no time).
# usage: solve-case.sh BIN_DIR RUN_DIR THREADS [ALLOW_FAILURE]
set -euo pipefail
bin=$1 run_dir=$2 threads=$3 allow_failure=${4:-0}
mapfile -t args < "$run_dir.args"
rm -f "$run_dir/wall_time.txt"
# Resumable: a checkpoint of an unfinished run, the same arguments, and no file they name
# (the scene, the point files) newer than the checkpoint.
resumable() {
  [ -f "$run_dir/checkpoint.h5" ] && cmp -s "$run_dir.args" "$run_dir/args.used" || return 1
  ! grep -qE '\] status: (finished|failed)' "$run_dir/log.txt" 2>/dev/null || return 1
  local word file
  for word in "${args[@]}"; do
    file=${word#*=}
    if [ -f "$file" ] && [ "$file" -nt "$run_dir/checkpoint.h5" ]; then return 1; fi
  done
}
if resumable; then
  echo "solve-case.sh: $run_dir continues from its checkpoint" >&2
  if [ -f "$run_dir/time.txt" ]; then cat "$run_dir/time.txt" >> "$run_dir/time-parts.txt"; fi
  solve=("$bin/latmpm-solve" --resume "$run_dir")
else
  mkdir -p "$run_dir"
  rm -f "$run_dir/time-parts.txt" "$run_dir/time.txt"
  cp "$run_dir.args" "$run_dir/args.used"
  solve=("$bin/latmpm-solve" "${args[@]}" -o "$run_dir")
fi
# /usr/bin/time gives the CPU time too (user + sys), which other load on the machine inflates
# less than the wall time; the solver's own wall time and rate are in its log.
solve_status=0
/usr/bin/time -f 'wall_s=%e\ncpu_s=%U+%S' -o "$run_dir/time.txt" \
  "${solve[@]}" --threads "$threads" --quiet > "$run_dir/summary.txt" \
  || solve_status=$?
if [ "$solve_status" -ne 0 ] && ! { [ "$solve_status" -eq 3 ] && [ "$allow_failure" = 1 ]; }; then
  exit "$solve_status"
fi
sed -i '/^Command exited with non-zero status/d' "$run_dir/time.txt"
reason=$(sed -n 's/^\[[^]]*\] stopped: //p' "$run_dir/log.txt" | tail -1)
status=$(grep '^\[.*\] status:' "$run_dir/log.txt" | tail -1 | sed 's/^\[[^]]*\] //')
# (a resumed run logs its bodies again: each body counts once)
points=$(awk '/\] body .*: [0-9]+ points$/ { k = $0; sub(/^\[[^]]*\] /, "", k); if (!seen[k]++) n += $(NF - 1) } END { print n }' "$run_dir/log.txt")
awk -v status="$status" -v points="$points" -v reason="$reason" -F= '
  $1 == "wall_s" { wall += $2 }
  $1 == "cpu_s" { split($2, c, "+"); cpu += c[1] + c[2] }
  END {
    n = split(status, f, " ")
    for (i = 1; i <= n; i++) { split(f[i], kv, "="); v[kv[1]] = kv[2] }
    printf "status=%s\nwall_s=%.1f\ncpu_s=%.1f\nsteps=%s\npoints=%s\nupdates_per_s=%s\n", f[2], wall, cpu, v["steps"], points, v["updates_per_s"]
    if (reason != "") printf "reason=%s\n", reason
  }' $([ -f "$run_dir/time-parts.txt" ] && echo "$run_dir/time-parts.txt") "$run_dir/time.txt" > "$run_dir/wall_time.txt.tmp"
mv "$run_dir/wall_time.txt.tmp" "$run_dir/wall_time.txt"
