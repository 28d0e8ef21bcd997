#!/usr/bin/env bash
# The lattice-stiffness table and plot from the static runs (pipelines/lattice-stiffness.mk).
# usage: table.sh OUT_DIR PLATE_MM LATTICE...
#   k   = load / travel of run-<l>-initial (linear elastic, one increment), N/mm
#   E*  = k H / A: H the height between the plates, A = footprint volume / H (latmpm-lattice), MPa
#   P_c = where run-<l>-path's static path ends (load maximum or no convergence), N, with the
#         travel there; "—" when it did not end within the travel
set -euo pipefail
out=$1 plate=$2
shift 2
csv=$out/stiffness.csv md=$out/stiffness.md
echo "lattice,k[N/mm],E_eff[MPa],instability_load[N],instability_travel[mm],end_reason,initial_cpu_s,path_cpu_s" > "$csv.tmp"
for l in "$@"; do
  geo=$out/geometry-$l.txt init=$out/run-$l-initial path=$out/run-$l-path
  # Second data row of the series: the one increment (travel m, load N).
  k=$(awk -F, 'NR == 3 { printf "%.6g", $4 / ($3 * 1e3) }' "$init/series.csv")
  read -r zmin zmax < <(sed -n 's/.* z \[\([-0-9.]*\), \([-0-9.]*\)\] mm.*/\1 \2/p' "$geo")
  fp=$(sed -n 's/.*\/ \([0-9.]*\) mm^3 footprint.*/\1/p' "$geo")
  e=$(awk -v k="$k" -v z0="$zmin" -v z1="$zmax" -v t="$plate" -v v="$fp" \
      'BEGIN { h = z1 - z0 - 2 * t; printf "%.4g", k * h * h / v }')  # N/mm · mm / mm² = MPa
  # status.toml's reason, as the static run writes it (libs/static_run/static_solve_run.cpp).
  end=$(sed -n 's/^reason = "the static path ends (\(.*\)) at travel \([-0-9.e+]*\) m, load \([-0-9.e+]*\) N"$/\1;\2;\3/p' "$path/status.toml" 2>/dev/null || true)
  if [ ! -f "$path/done" ]; then
    reason="path not run" travel="" load=""
  elif [ -n "$end" ]; then
    IFS=';' read -r reason travel load <<< "$end"
    travel=$(awk -v x="$travel" 'BEGIN { printf "%.4g", x * 1e3 }')
  else
    reason="none within the travel" travel="" load=""
  fi
  ci=$(sed -n 's/^cpu_s = //p' "$init/status.toml") cp=$(sed -n 's/^cpu_s = //p' "$path/status.toml" 2>/dev/null || true)
  echo "$l,$k,$e,$load,$travel,$reason,$ci,$cp" >> "$csv.tmp"
done
mv "$csv.tmp" "$csv"
{
  echo "# Lattice stiffness from the static solver"
  echo
  echo "Initial stiffness k (linear elastic, one increment), effective modulus E* = k H / A and"
  echo "the first instability of the neo-Hookean static path (docs/statics.md). Made by"
  echo "pipelines/lattice-stiffness.mk in $out."
  echo
  echo "| lattice | k (N/mm) | E* (MPa) | instability load (N) | at travel (mm) | path ends by | CPU initial / path (s) |"
  echo "|---|---|---|---|---|---|---|"
  awk -F, 'NR > 1 { printf "| %s | %s | %s | %s | %s | %s | %s / %s |\n", $1, $2, $3, ($4 == "" ? "—" : $4), ($5 == "" ? "—" : $5), $6, $7, $8 }' "$csv"
} > "$md"
# The instability panel only when some path ended (gnuplot refuses an all-empty column).
ended=$(awk -F, 'NR > 1 && $4 != "" { n++ } END { print n + 0 }' "$csv")
panel2=""
if [ "$ended" -gt 0 ]; then
  panel2='set ylabel "load (N)"; set title "first instability load (static path end)";
plot "'"$csv"'" every ::1 using 0:4:xtic(1) with boxes notitle'
fi
gnuplot <<PLOT
set terminal pngcairo size $([ "$ended" -gt 0 ] && echo 900 || echo 450),420
set output "$out/stiffness.png"
set datafile separator ","
set multiplot layout 1,$([ "$ended" -gt 0 ] && echo 2 || echo 1)
set style fill solid 0.6
set boxwidth 0.6
set xtics rotate by 30 right
set yrange [0:*]
set ylabel "E* (MPa)"
set title "effective modulus (static, linear elastic)"
plot "$csv" every ::1 using 0:3:xtic(1) with boxes notitle
$panel2
unset multiplot
PLOT
echo "table.sh: $md" >&2
