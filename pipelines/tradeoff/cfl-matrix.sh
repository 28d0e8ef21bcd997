#!/bin/bash
# The stable CFL number per shape function, measured (docs/tradeoff.md, "Time step"): paper
# A's column (t = 1.6 mm, L = 16 mm, data/scenes/column-tiny.toml) at cell 0.4 mm, 2 points
# per cell, compressed 1 mm at 100 mm/s, mass scaling 6, for every shape at cfl 0.3 ... 1.0.
# Per run: how it ended, steps, CPU s (status.toml), the energy balance's error at the end over
# the external work (latmpm-post's checks.csv energy_error_over_work: 0 for an exact,
# dissipation-free scheme; a blow-up shows as a failed run or a growing error) and the final
# load's change against the same shape at cfl 0.3 (its comparison.csv final_error). Every
# number is latmpm-post's (OUT_DIR/post-<shape>/); this script copies them.
#   pipelines/tradeoff/cfl-matrix.sh BIN OUT_DIR > cfl-matrix.csv
set -euo pipefail
bin=$1; out=$2
src=$(cd "$(dirname "$0")/../.." && pwd)
mkdir -p "$out"
[ -f "$out/c-points.h5" ] || {
  "$bin/latmpm-lattice" --column --diameter 1.6mm --length 16mm --end-plates 0.8mm --quiet -o "$out/c.h5"
  "$bin/latmpm-voxelize" "$out/c.h5" --cell 0.4mm --ppc 2 --quiet -o "$out/c-points.h5" 2>/dev/null
}
source "$src/pipelines/common/post-metric.sh"
cfls="0.3 0.5 0.6 0.7 0.8 0.9 1.0"
echo "shape,cfl,status,steps,cpu_s,energy_error_over_work,load_fixed_N,load_change_vs_cfl0.3"
for shape in linear ugimp cpgimp bspline2 bspline3 ddmp; do
  runs=()
  for cfl in $cfls; do
    run="$out/$shape-cfl$cfl"
    [ -f "$run/status.toml" ] && grep -q 'status = "\(finished\|failed\)"' "$run/status.toml" ||
      nice "$bin/latmpm-solve" "$src/data/scenes/column-tiny.toml" --set points.0.file="$out/c-points.h5" \
        --set grid.cell=0.4mm --set grid.shape=$shape --set time.cfl=$cfl --set output.snapshot_every=1000000 \
        --threads 1 --quiet -o "$run" > "$run.log" 2>&1 || true
    runs+=(--label "cfl$cfl=$run" "$run")
  done
  # The numbers: latmpm-post's checks.csv (energy_error / external_work at the end, the final
  # load_fixed) and comparison.csv (the final load against cfl 0.3); docs/post.md.
  post=$out/post-$shape
  "$bin/latmpm-post" "${runs[@]}" -o "$post" --load load_fixed --reference cfl0.3 > /dev/null
  for cfl in $cfls; do
    run="$out/$shape-cfl$cfl"
    status=$(sed -n 's/^status = "\(.*\)"/\1/p' "$run/status.toml")
    steps=$(sed -n 's/^steps = //p' "$run/status.toml")
    cpu=$(sed -n 's/^cpu_s = //p' "$run/status.toml")
    ee=$(post_metric "$post/checks.csv" "cfl$cfl" energy_error_over_work)
    lf=$(post_metric "$post/checks.csv" "cfl$cfl" final_load)
    change=$(post_comparison "$post/comparison.csv" cfl0.3 "cfl$cfl" final_error)
    # A failed run has no energy error or change: leave the cell empty rather than print 0.
    [ -n "$ee" ] && ee=$(printf "%.4f" "$ee")
    [ -n "$change" ] && change=$(printf "%+.4f" "$change")
    printf "%s,%s,%s,%s,%.2f,%s,%.4g,%s\n" "$shape" "$cfl" "$status" "$steps" "$cpu" "$ee" "$lf" "$change"
  done
done
