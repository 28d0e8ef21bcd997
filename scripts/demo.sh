#!/usr/bin/env bash
# The default experiment, end to end with the tools that exist so far:
# the paper's T2P30 tetrahedral lattice and its summary, then its material points.
set -euo pipefail
bin_dir=${1:?usage: demo.sh BIN_DIR RESULTS_DIR}
out=${2:?usage: demo.sh BIN_DIR RESULTS_DIR}
export PATH="$bin_dir:$PATH"
mkdir -p "$out"
echo "== latmpm demo: T2P30 lattice (paper A), results in $out"
latmpm-lattice --preset T2P30 -o "$out/t2p30.h5" --stl "$out/t2p30.stl" --voxel 0.2mm
if command -v latmpm-voxelize >/dev/null; then
  latmpm-voxelize "$out/t2p30.h5" --cell 0.64mm --ppc 2 -o "$out/t2p30-points.h5"
fi
echo "== done: $(ls "$out" | tr '\n' ' ')"
