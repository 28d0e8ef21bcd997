#!/usr/bin/env bash
# Voxelizer benchmarks (docs/benchmarks.md, "Voxelizer"):
#  1. paper A's T2P30 at the paper's resolution (0.64 mm cells, 2 ppc) from its strut graph;
#  2. the same specimen as an STL of about a million triangles (latmpm-lattice --stl at
#     0.32 mm voxels), checks included.
# Wall time median of 5 (3 for the STL) runs, peak resident memory from /usr/bin/time -v.
# usage: bench/voxelize/run.sh BIN_DIR
set -euo pipefail
bin=$(cd "${1:?usage: run.sh BIN_DIR}" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

# median_run N LABEL COMMAND...: runs COMMAND N times, prints median wall s and max peak RSS.
median_run() {
  local n=$1 label=$2
  shift 2
  local times=() peak=0
  for _ in $(seq "$n"); do
    /usr/bin/time -v "$@" 2> time.txt >/dev/null
    times+=("$(awk -F': ' '/Elapsed \(wall clock\)/ {n = split($2, t, ":"); s = 0; for (i = 1; i <= n; ++i) s = s * 60 + t[i]; print s}' time.txt)")
    local rss
    rss=$(awk -F': ' '/Maximum resident set size/ {print $2}' time.txt)
    (( rss > peak )) && peak=$rss
  done
  local median
  median=$(printf '%s\n' "${times[@]}" | sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}')
  printf '%-44s median %6.2f s wall (runs: %s), peak RSS %d MB\n' "$label" "$median" "${times[*]}" $((peak / 1024))
}

"$bin/latmpm-lattice" --preset T2P30 -o t2p30.h5 --quiet
median_run 5 "T2P30 strut graph, 0.64 mm, 2 ppc" \
  "$bin/latmpm-voxelize" t2p30.h5 --cell 0.64mm --ppc 2 -o points.h5 --quiet
"$bin/latmpm-voxelize" t2p30.h5 --cell 0.64mm --ppc 2 -o points.h5 2>&1 | grep -E "points:|volume:|time:"

"$bin/latmpm-lattice" --preset T2P30 --stl t2p30.stl --voxel 0.32mm -o /dev/null --quiet
echo "STL: $(( ($(stat -c %s t2p30.stl) - 84) / 50 )) triangles"
median_run 3 "T2P30 STL, 0.64 mm, 2 ppc (with checks)" \
  "$bin/latmpm-voxelize" t2p30.stl --units mm --cell 0.64mm --ppc 2 -o points.h5 --quiet
"$bin/latmpm-voxelize" t2p30.stl --units mm --cell 0.64mm --ppc 2 -o points.h5 2>&1 | grep -E "mesh:|points:|volume:|time:"
