#!/usr/bin/env bash
# Appends to OUT_DIR/summary.md (written by latmpm-post) the set-up notes (a Markdown file)
# and a table of the runs' cost: points, steps, wall and CPU time, particle-updates per second
# (from each RUN_DIR/wall_time.txt, pipelines/common/solve-case.sh); also OUT_DIR/runs.csv.
# usage: append-runs.sh OUT_DIR NOTES.md LABEL=RUN_DIR...
set -euo pipefail
out=$1 notes=$2
shift 2
csv="$out/runs.csv"
{
  echo
  cat "$notes"
  echo
  echo "## Cost of each run"
  echo
  echo "Measured by the pipeline (\`wall_time.txt\` in each run directory; CPU = user + system)."
  echo
  echo "| run | points | steps | wall (s) | CPU (s) | particle-updates/s |"
  echo "|---|---|---|---|---|---|"
} >> "$out/summary.md"
echo "run,points,steps,wall[s],cpu[s],updates_per_s" > "$csv.tmp"
for label_run in "$@"; do
  name=${label_run%%=*} run=${label_run#*=}
  awk -F= -v name="$name" -v csv="$csv.tmp" -v md="$out/summary.md" '
    { v[$1] = $2 }
    END {
      printf "| %s | %s | %s | %s | %s | %.3g |\n", name, v["points"], v["steps"], v["wall_s"], v["cpu_s"], v["updates_per_s"] >> md
      printf "%s,%s,%s,%s,%s,%s\n", name, v["points"], v["steps"], v["wall_s"], v["cpu_s"], v["updates_per_s"] >> csv
    }' "$run/wall_time.txt"
done
mv "$csv.tmp" "$csv"
