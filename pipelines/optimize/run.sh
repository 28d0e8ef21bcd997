#!/usr/bin/env bash
# Runs the paper C examples with latmpm-optimize and writes summary.md (pipelines/optimize.mk).
# usage: run.sh BIN_DIR OUT_DIR quick|paper
set -euo pipefail
bin=$1 out=$2 mode=$3
src=$(cd "$(dirname "$0")/../.." && pwd)
mkdir -p "$out"
run() {  # name scene [--set ...]
  local name=$1 scene=$2
  shift 2
  echo "optimize: $name"
  "$bin/latmpm-optimize" "$src/data/optimize/$scene" "$@" -o "$out/$name" --quiet --threads 2
  if command -v gnuplot >/dev/null; then
    for gp in "$out/$name"/*-design.gp; do (cd "$out/$name" && gnuplot "$(basename "$gp")"); done
  fi
}
if [ "$mode" = quick ]; then
  # The scenes' sizes (2D 60x20, 3D 24x8x6 cells): smaller grids leave too few cells across
  # the kernel (1.5 cells) for LETO; 100 iterations at most, the band ramp over 40.
  quick=(--set optimize.max_iterations=100 --set leto.band_ramp=40 --set simp.beta_every=20)
  run beam-2d cantilever-2d.toml "${quick[@]}"
  run beam-3d beam-3d.toml "${quick[@]}"
  examples="beam-2d beam-3d"
else
  run beam-2d cantilever-2d.toml
  run michell-2d michell-2d.toml
  run distributed-2d distributed-2d.toml
  run distributed-2d-no-band distributed-2d.toml --set optimize.methods=leto --set leto.narrow_band=false
  run beam-3d beam-3d.toml
  examples="beam-2d michell-2d distributed-2d distributed-2d-no-band beam-3d"
fi
python3 "$src/pipelines/optimize/summary.py" "$out" $examples > "$out/summary.md.tmp"
mv "$out/summary.md.tmp" "$out/summary.md"
echo "optimize: results in $out/summary.md"
