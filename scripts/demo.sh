#!/usr/bin/env bash
# make demo: the default experiment end to end, in a few minutes on 2 cores.
# A small tetrahedral lattice (paper A's T2P30 cell: struts 8 mm long, 2.4 mm thick, 30 deg;
# 2x2x2 cells) between printed plates, compressed 6 mm (32 % strain) at 100 mm/s by the top plate
# (driven, rigid) against the bottom plate (fixed, rigid); E = 10 MPa, nu = 0.4,
# rho = 6 rho0, uGIMP, cell 0.64 mm with 2 points per cell per direction (paper A Sec. 5.1).
# Chain: latmpm-lattice -> latmpm-voxelize -> latmpm-solve -> latmpm-post; ends with the
# load-displacement plot and the metrics table in RESULTS_DIR.
# usage: demo.sh BIN_DIR RESULTS_DIR
set -euo pipefail
bin_dir=${1:?usage: demo.sh BIN_DIR RESULTS_DIR}
out=${2:?usage: demo.sh BIN_DIR RESULTS_DIR}
source_dir=$(cd "$(dirname "$0")/.." && pwd)
export PATH="$bin_dir:$PATH"
mkdir -p "$out"
start=$(date +%s)

echo "== 1/4 latmpm-lattice: T2P30 cell, 2x2x2 cells, 1.28 mm plates"
latmpm-lattice --preset T2P30 --cells 2x2x2 --plates 1.28mm -o "$out/lattice.h5" \
  --stl "$out/lattice.stl" --voxel 0.2mm

echo "== 2/4 latmpm-voxelize: cell 0.64 mm, 2 points per cell per direction"
latmpm-voxelize "$out/lattice.h5" --cell 0.64mm --ppc 2 -o "$out/points.h5"

echo "== 3/4 latmpm-solve: the top plate driven down 6 mm at 100 mm/s"
latmpm-solve "$source_dir/pipelines/lattice-compression/lattice.toml" \
  --set points.0.file="$out/points.h5" --set run.end.plate_displacement=6mm \
  --set output.series_every=25 -o "$out/run"

echo "== 4/4 latmpm-post: load-displacement plot, metrics"
latmpm-post "$out/run" -o "$out" --label T2P30-2x2x2="$out/run" \
  --title "Demo: T2P30 lattice, 2x2x2 cells, compressed 6 mm" --fit-range 0.5mm:2mm

echo
sed -n '/^## Compression/,/^## Plots/p' "$out/summary.md" | sed '$d'
echo "== done in $(( $(date +%s) - start )) s. Results in $out/:"
echo "   summary.md (metrics, notes), metrics.csv, plots/load_displacement.png (and .svg),"
echo "   curves/ (load-displacement CSV), run/ (series.csv, log.txt, snapshots.xmf for ParaView)"
