#!/usr/bin/env bash
# The lattice-stiffness table and plot from the static runs (pipelines/lattice-stiffness.mk).
# usage: table.sh BIN OUT_DIR LATTICE...
#   k   = initial stiffness of run-<l>-initial (linear elastic, one increment: the secant), N/mm
#   E*  = k H / A: H the lattice height between the plates, A its footprint, MPa
#         (both from latmpm-post's metrics.csv over the initial runs, OUT_DIR/initial/;
#         definitions in docs/post.md)
#   P_c = where run-<l>-path's static path ends (load maximum, indefinite tangent, or a Newton
#         failure at the smallest step), N, with the travel there; "—" when it did not end
#         within the travel
# Every number is computed by latmpm-post or the static run (status.toml); this script copies.
set -euo pipefail
bin=$1 out=$2
shift 2
csv=$out/stiffness.csv md=$out/stiffness.md
post=$out/initial
labels=() runs=()
for l in "$@"; do labels+=(--label "$l=$out/run-$l-initial"); runs+=("$out/run-$l-initial"); done
"$bin/latmpm-post" "${runs[@]}" "${labels[@]}" -o "$post" --kind compression --load load_driven \
  --title "Lattice stiffness: the initial increments" > /dev/null
source "$(dirname "$0")/../common/post-metric.sh"
echo "lattice,k[N/mm],E_eff[MPa],instability_load[N],instability_travel[mm],end_reason,initial_cpu_s,path_cpu_s" > "$csv.tmp"
for l in "$@"; do
  init=$out/run-$l-initial path=$out/run-$l-path
  k=$(post_metric "$post/metrics.csv" "$l" initial_stiffness) e=$(post_metric "$post/metrics.csv" "$l" effective_modulus)
  if [ -z "$e" ]; then
    echo "table.sh: no effective modulus for $l in $post/summary.md (a point file from before latmpm-lattice" \
         "recorded footprint_area? remove $out/geometry-$l.h5 and $out/points-$l.h5 and rerun)" >&2
    exit 2
  fi
  e=$(printf '%.4g' "$e")
  # status.toml's reason, as the static run writes it (libs/static_run/static_solve_run.cpp).
  end=$(sed -n 's/^reason = "the static path ends (\(.*\)) at travel \([-0-9.e+]*\) m, load \([-0-9.e+]*\) N"$/\1;\2;\3/p' "$path/status.toml" 2>/dev/null || true)
  # A path stopped before it ended (a run killed or still going, no done stamp): how far its
  # series got, stable all the way (the last row of series.csv: travel m, load N).
  last=$(tail -n 1 "$path/series.csv" 2>/dev/null | awk -F, 'NR == 1 && $3 + 0 > 0 && $11 == 1 { printf "%.4g mm (%.4g N)", $3 * 1e3, $4 }' || true)
  if [ ! -f "$path/done" ] && [ -n "$last" ]; then
    reason="path stopped unfinished: stable to $last" travel="" load=""
  elif [ ! -f "$path/done" ]; then
    reason="path not run" travel="" load=""
  elif [ -n "$end" ]; then
    IFS=';' read -r reason travel load <<< "$end"
    # Newton's own failure texts (projected_newton.cpp; with commas): the table names the
    # kind, status.toml and log.txt keep the text. Any other reason passes, its commas made
    # semicolons so that the CSV row stays whole.
    case "$reason" in
      "no convergence in "* | "converging linearly"* | "no progress"* | "the line search"* | "the projected Hessian"*)
        reason="Newton failure at the smallest step" ;;
      *) reason=${reason//,/;} ;;
    esac
    travel=$(awk -v x="$travel" 'BEGIN { printf "%.4g", x * 1e3 }')  # m -> mm
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
  panel2='set ylabel "load (N)"; set title "first instability (static path end): load, travel";
plot "'"$csv"'" every ::1 using 0:4:xtic(1) with boxes notitle, "" every ::1 using 0:4:(sprintf("%.1f mm", $5)) with labels offset 0,0.7 font ",9" notitle'
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
