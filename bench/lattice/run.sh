#!/usr/bin/env bash
# Lattice benchmark: T2P30 strut graph, its surface and STL at 0.1 mm voxels (medians), the
# default tool run, and STEP export times for growing lattices. Results: docs/benchmarks.md.
# usage: bench/lattice/run.sh BIN_DIR   (set LATMPM_BENCH_STEP_FULL=1 for the full T2P30 STEP)
set -euo pipefail
bin_dir=${1:?usage: bench/lattice/run.sh BIN_DIR}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cd "$scratch"
echo "-- library: T2P30 graph, surface and STL at 0.1 mm"
"$bin_dir/bench_lattice" 0.1 3 "$scratch/bench.stl"
echo "-- tool: latmpm-lattice --preset T2P30 --stl t2p30.stl --voxel 0.1mm -o t2p30.h5"
/usr/bin/time -f "   wall %e s, user %U s, peak %M kB" \
  "$bin_dir/latmpm-lattice" --preset T2P30 --stl t2p30.stl --voxel 0.1mm -o t2p30.h5 --quiet
echo "-- tool: latmpm-lattice --preset T2P30 -o t2p30.h5 (with the summary's level set at t/16)"
/usr/bin/time -f "   wall %e s, user %U s, peak %M kB" \
  "$bin_dir/latmpm-lattice" --preset T2P30 -o t2p30.h5 2>&1 | tail -1
cells="1x1x1 2x2x2 3x3x3"
[ "${LATMPM_BENCH_STEP_FULL:-0}" = 1 ] && cells="$cells 5x5x5"
for c in $cells; do
  echo "-- STEP: latmpm-lattice --preset T2P30 --cells $c --step t.step"
  /usr/bin/time -f "   wall %e s, peak %M kB" \
    "$bin_dir/latmpm-lattice" --preset T2P30 --cells "$c" --step t.step --quiet
done
