#!/usr/bin/env bash
# Appends to OUT_DIR/summary.md (written by latmpm-post) the set-up notes (a Markdown file)
# and a table of the runs' cost as each RUN_DIR/status.toml records it (latmpm-solve writes it
# at the end of every run: points, steps, wall and CPU time over all parts of a resumed run,
# particle-updates per second, peak memory, the machine: the same run costs several times more
# CPU on one processor than another, docs/experiments.md); also OUT_DIR/runs.csv.
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
  echo "As each run's \`status.toml\` records it (latmpm-solve; CPU = user + system, the whole process)."
  echo
  echo "| run | status | points | steps | wall (s) | CPU (s) | particle-updates/s | peak memory (MB) | machine |"
  echo "|---|---|---|---|---|---|---|---|---|"
} >> "$out/summary.md"
echo "run,status,points,steps,wall[s],cpu[s],updates_per_s,peak_memory[MB],cpu_model,vector_isa" > "$csv.tmp"
for label_run in "$@"; do
  name=${label_run%%=*} run=${label_run#*=}
  awk -v name="$name" -v csv="$csv.tmp" -v md="$out/summary.md" '
    # key = value lines of a flat TOML table; strings lose their quotes
    /^[a-z_]+ = / { k = $1; v = substr($0, length(k) + 4); gsub(/^"|"$/, "", v); s[k] = v }
    END {
      # Runs recorded before status.toml named the machine (2026-11-28) have no cpu_model.
      cpu = ("cpu_model" in s) ? s["cpu_model"] : "not recorded"; isa = s["vector_isa"]; gsub(/,/, ";", cpu)
      printf "| %s | %s | %s | %s | %.1f | %.1f | %.3g | %.0f | %s%s |\n", name, s["status"], s["points"], s["steps"],
        s["wall_s"], s["cpu_s"], s["updates_per_s"], s["peak_memory_mb"], cpu, (isa == "" ? "" : " (" isa ")") >> md
      printf "%s,%s,%s,%s,%.1f,%.1f,%.4g,%.0f,%s,%s\n", name, s["status"], s["points"], s["steps"],
        s["wall_s"], s["cpu_s"], s["updates_per_s"], s["peak_memory_mb"], cpu, isa >> csv
    }' "$run/status.toml"
done
mv "$csv.tmp" "$csv"
