#!/usr/bin/env bash
# Issue 14's levers on the QUICK impact scene (docs/tradeoff.md, "Impact"): T2P30-E10, 2x2x2
# cells, a 0.64 kg flyer at 2 m/s, 20 ms; the reference at cfl 0.3 with the printed base held,
# the same with every position perturbed by 1e-9 (cell 1.000000001 mm), cfl 0.4, the base
# omitted for a fixed half-space on its face, and both; then latmpm-post --kind impact
# against the reference (OUT/post/summary.md, metrics.csv). Needs results/impact/quick/
# points-T2P30.h5 (make impact QUICK=1, or its points-T2P30.h5 target). One solver thread each.
# usage: impact-levers.sh BIN_DIR OUT_DIR
set -euo pipefail
bin=$1 out=$2
script=impact-levers.sh
source "$(dirname "$0")/impact-quick-row.sh"
mkdir -p "$out"
base=(--set bodies.bottom_plate.role=omitted --set rigid_bodies.base.motion=fixed --set rigid_bodies.base.shape=half_space
      --set 'rigid_bodies.base.point=["0mm","0mm","2mm"]' --set 'rigid_bodies.base.normal=[0,0,1]')
run() {
  local name=$1
  shift
  rm -rf "${out:?}/$name"
  "$bin/latmpm-solve" pipelines/impact/impact.toml "${row[@]}" "$@" -o "$out/$name"
}
run ref --set time.cfl=0.3
run ref-perturbed --set time.cfl=0.3 --set grid.cell=1.000000001mm
run cfl04 --set time.cfl=0.4
run rigid-base --set time.cfl=0.3 "${base[@]}"
run rigid-base-cfl04 --set time.cfl=0.4 "${base[@]}"
labels=()
for name in ref ref-perturbed cfl04 rigid-base rigid-base-cfl04; do labels+=(--label "$name=$out/$name"); done
"$bin/latmpm-post" "$out"/{ref,ref-perturbed,cfl04,rigid-base,rigid-base-cfl04} --kind impact --reference ref "${labels[@]}" -o "$out/post"
