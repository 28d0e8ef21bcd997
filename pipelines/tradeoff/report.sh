#!/usr/bin/env bash
# The trade-off table and Pareto plot: for every run of OUT_DIR/knobs.txt (written by
# pipelines/tradeoff.mk, one FAMILY:NAME per line, the reference run first in each family;
# its cell, points per cell, shape, scheme, mass scaling and speed are its row of
# pipelines/tradeoff/FAMILY.txt), its cost (OUT_DIR/FAMILY/run-NAME/status.toml) and its
# errors against the reference and the base case, as latmpm-post computed them
# (OUT_DIR/FAMILY/comparison.csv, latmpm-post --reference ref --reference base; definitions in
# docs/post.md "Comparing runs"). Writes OUT_DIR/errors.csv, OUT_DIR/pareto.gp,
# pareto.png, pareto.svg (when gnuplot is there) and OUT_DIR/summary.md.
# usage: report.sh OUT_DIR
set -euo pipefail
out=$1
here=$(dirname "$0")
source "$here/../common/post-metric.sh"
csv="$out/errors.csv"
echo "family,run,cell[mm],ppc,shape,mass_scaling,speed[mm/s],points,steps,cpu[s],wall[s],curve_error,peak_error,late_error,euler_error,ke_over_se,status,curve_change_vs_base" > "$csv.tmp"
# status KEY RUN_DIR: a value of RUN_DIR/status.toml (latmpm-solve), strings without quotes.
status() { sed -n "s/^$1 = //p" "$2/status.toml" | sed 's/^"\(.*\)"$/\1/'; }
while IFS=: read -r family name; do
  [ -n "$family" ] || continue
  run="$out/$family/run-$name"
  # The knobs from the solver arguments of the row (KEY=VALUE words; scheme USL unless set).
  words=$(bash "$here/../common/case-table.sh" args "$here/$family.txt" "$name" "$out/$family" | paste -sd' ')
  knob() { echo "$words" | tr ' ' '\n' | sed -n "s/^$1=//p" | tail -1; }
  cell=$(knob grid.cell); cell=${cell%mm}
  ppc=$(knob points.0.file); ppc=${ppc##*-p}; ppc=${ppc%.h5}
  shape=$(knob grid.shape); scheme=$(knob grid.scheme); scheme=${scheme:-usl}
  ms=$(knob time.mass_scaling)
  speed=$(knob bodies.top_plate.velocity | sed 's/.*"-\([0-9.]*\)mm\/s"\]$/\1/')
  cost="$(status points "$run"),$(status steps "$run"),$(printf %.1f "$(status cpu_s "$run")"),$(printf %.1f "$(status wall_s "$run")")"
  ended=$(status status "$run")
  if [ "$ended" = failed ]; then
    # A numerical failure: no errors, the step and the reason in short.
    errors=",,,,"
    change=""
    # "numerical failure: step N (t = …): what, …; the fastest particle …" → "step N: what"
    # (no comma: a field of the CSV below).
    reason=$(status reason "$run")
    short=$(sed -n 's/^numerical failure: \(step [0-9]*\) ([^)]*): \([^;,]*\).*/\1: \2/p' <<< "$reason")
    reason=${reason//,/;}
    ended="failed at ${short:-$reason}"
  else
    # latmpm-post's comparison.csv against the reference; the change against the base case
    # isolates the knob from the base's own error.
    cmp="$out/$family/comparison.csv" errors=""
    for e in curve_error peak_error late_error euler_error ke_over_se; do
      errors+="${errors:+,}$(post_comparison "$cmp" ref "$name" $e)"
    done
    change=$(post_comparison "$cmp" base "$name" curve_error)
  fi
  echo "$family,$name,$cell,$ppc,$shape${scheme:+ ($scheme)},$ms,$speed,$cost,$errors,$ended,$change" >> "$csv.tmp"
done < "$out/knobs.txt"
mv "$csv.tmp" "$csv"

# Pareto plot: CPU time against the curve error, one colour per family; the line joins each
# family's Pareto front (no cheaper run has a smaller error). The reference (error 0) is left out.
awk -F, 'NR > 1 && $2 != "ref" && $12 != "" { print $1, $10, $12, $2 }' "$csv" | sort -k1,1 -k2,2g > "$out/pareto-points.dat"
awk '{ if ($1 != fam) { fam = $1; best = 1e300; print "" ; print "" } if ($3 < best) { best = $3; print } }' \
  "$out/pareto-points.dat" | sed '1,2d' > "$out/pareto-front.dat"
cat > "$out/pareto.gp" <<'GP'
# Trade-off: CPU time of a run against its error (pipelines/tradeoff/report.sh)
set logscale xy
set xlabel "CPU time of the run (s, one thread)"
set ylabel "load-displacement error against the finest run"
set key below
set grid
set title "Speed against accuracy: one knob at a time (labels: the knob changed)"
plot "pareto-points.dat" using 2:(strcol(1) eq "column" ? $3 : 1/0):(strcol(4)) with labels offset 0,0.7 font ",8" tc lt 1 notitle, \
     "" using 2:(strcol(1) eq "column" ? $3 : 1/0) with points pt 7 lc 1 title "column t = 1.6 mm (ref: cell 0.2 mm)", \
     "" using 2:(strcol(1) eq "lattice" ? $3 : 1/0):(strcol(4)) with labels offset 0,-0.7 font ",8" tc lt 2 notitle, \
     "" using 2:(strcol(1) eq "lattice" ? $3 : 1/0) with points pt 5 lc 2 title "T2P30 2x2x1 (ref: cell 0.4 mm)", \
     "pareto-front.dat" index 0 using 2:3 with lines lc 1 dt 2 title "Pareto front, column", \
     "" index 1 using 2:3 with lines lc 2 dt 2 title "Pareto front, lattice"
GP
if command -v gnuplot > /dev/null; then
  (cd "$out" && gnuplot -e 'set terminal pngcairo size 1000,700; set output "pareto.png"' pareto.gp \
   && gnuplot -e 'set terminal svg size 1000,700; set output "pareto.svg"' pareto.gp)
fi

{
  echo "# Trade-off: speed against accuracy"
  echo
  echo "Made by \`make tradeoff\` (pipelines/tradeoff.mk) on $(date -u +%Y-%m-%d). Cost: CPU time of"
  echo "the solver (user + system, one thread per run under \`make -j2\`) and wall time. Errors"
  echo "against each family's reference (\`ref\`, the finest run), definitions in"
  echo "docs/post.md (\"Comparing runs\", computed by latmpm-post --reference): curve = relative L2"
  echo "difference of the binned load-displacement curves; peak = peak load; late = post-buckling"
  echo "load (column) or work ∫F du (lattice); Euler = column post-buckling load against the Euler load;"
  echo "KE/SE = largest kinetic / strain energy over the second half of the travel; curve change vs"
  echo "base = the curve error of the run against the base case (the knob's own effect)."
  echo
  echo "| family | run | cell (mm) | ppc | shape | mass scaling | v0 (mm/s) | points | steps | CPU (s) | wall (s) | curve error | peak error | late error | Euler error | KE/SE | curve change vs base |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
  awk -F, 'NR > 1 {
    if ($17 != "finished") {
      printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | **%s** | | | | | |\n", $1, $2, $3, $4, $5, $6, $7, $8, $9, $10, $11, $17
      next
    }
    printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %.1f %% | %+.1f %% | %+.1f %% | %s | %.2g | %.1f %% |\n",
      $1, $2, $3, $4, $5, $6, $7, $8, $9, $10, $11, 100 * $12, 100 * $13, 100 * $14,
      ($15 == "" ? "–" : sprintf("%+.1f %%", 100 * $15)), $16, 100 * $18 }' "$csv"
  echo
  echo "![Pareto plot](pareto.png)"
  echo
  echo "Plots of every family: [column/summary.md](column/summary.md), [lattice/summary.md](lattice/summary.md)."
} > "$out/summary.md.tmp"
mv "$out/summary.md.tmp" "$out/summary.md"
