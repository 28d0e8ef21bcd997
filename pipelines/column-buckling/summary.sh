#!/usr/bin/env bash
# Summary of the column cases: peak load, the load plateau after buckling, the Euler load and
# their ratios, the wall time of each run. Writes a Markdown table (stdout) and OUT_DIR/summary.csv.
#
# Euler load P = pi^2 E I / (K L)^2, I = pi t^4 / 64 (paper A Sec. 4). K = 0.5, clamped-clamped:
# the base plate holds its nodes at rest and the driven plate moves its nodes at v0, and the
# column's end points share those nodes, so neither end can rotate or move sideways (the
# paper's FEM check constrains the top the same way).
# usage: summary.sh OUT_DIR E_Pa L_m K CASE...   (CASE = t<diameter mm>-a<label>[-suffix...], e.g. t2.4-a0.02L-v50)
set -euo pipefail
out_dir=$1 E=$2 L=$3 K=$4
shift 4
csv="$out_dir/summary.csv"
echo "case,t[mm],a,peak_load[N],plateau_load[N],euler_load[N],peak/euler,plateau/euler,steps,wall[s]" > "$csv.tmp"
echo "| case | t (mm) | a | peak load (N) | plateau load (N) | Euler load, K = $K (N) | peak / Euler | plateau / Euler | steps | wall time (s) |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for case in "$@"; do
  t=${case#t}; t=${t%%-a*}; a=${case##*-a}; a=${a%%-*}
  curve="$out_dir/load-displacement-$case.csv"
  wall=$(sed -n 's/^wall_s=//p' "$out_dir/run-$case/wall_time.txt")
  steps=$(sed -n 's/.*status: finished steps=\([0-9]*\).*/\1/p' "$out_dir/run-$case/log.txt")
  # Plateau: the mean load over the last quarter of the plate travel (after buckling).
  awk -F, -v E="$E" -v L="$L" -v K="$K" -v t="$t" -v a="$a" -v name="$case" -v wall="$wall" \
      -v steps="$steps" -v csv="$csv.tmp" '
    NR > 1 { n++; d[n] = $1; p[n] = $2; if ($2 > peak) peak = $2 }
    END {
      pi = 3.141592653589793
      I = pi * (t * 1e-3) ^ 4 / 64
      euler = pi ^ 2 * E * I / (K * L) ^ 2
      for (i = 1; i <= n; i++) if (d[i] >= 0.75 * d[n]) { sum += p[i]; m++ }
      plateau = m ? sum / m : 0
      printf "| %s | %s | %s | %.4g | %.4g | %.4g | %.3f | %.3f | %s | %s |\n", name, t, a, peak, plateau, euler, peak / euler, plateau / euler, steps, wall
      printf "%s,%s,%s,%.6g,%.6g,%.6g,%.4f,%.4f,%s,%s\n", name, t, a, peak, plateau, euler, peak / euler, plateau / euler, steps, wall >> csv
    }' "$curve"
done
mv "$csv.tmp" "$csv"
