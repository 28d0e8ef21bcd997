#!/usr/bin/env bash
# Issue 14's quasi-static lever on the impact (docs/tradeoff.md, "Impact: mass scaling"):
# the QUICK impact scene (T2P30-E10, 2x2x2 cells, a 0.64 kg flyer at 2 m/s, gravity, 20 ms,
# uGIMP at its default cfl) with the deformable bodies' density scaled by S = 1 (the
# reference: paper A's real density), 2, 4, 9, 16 and 36 — the step grows as sqrt(S) — then
# latmpm-post --kind impact against S = 1 (OUT/post/summary.md, metrics.csv). The flyer's mass
# is not scaled (a rigid body's own mass). Needs results/impact/quick/points-T2P30.h5 (make
# impact QUICK=1). One solver thread each.
# usage: impact-mass-scaling.sh BIN_DIR OUT_DIR
set -euo pipefail
bin=$1 out=$2
script=impact-mass-scaling.sh
source "$(dirname "$0")/impact-quick-row.sh"
mkdir -p "$out"
scales=(1 2 4 9 16 36)
labels=() dirs=()
for s in "${scales[@]}"; do
  rm -rf "${out:?}/ms$s"
  "$bin/latmpm-solve" pipelines/impact/impact.toml "${row[@]}" --set time.mass_scaling="$s" -o "$out/ms$s"
  labels+=(--label "ms$s=$out/ms$s") dirs+=("$out/ms$s")
done
"$bin/latmpm-post" "${dirs[@]}" --kind impact --reference ms1 "${labels[@]}" -o "$out/post"
