#!/bin/bash
# The state digest of every shape x scheme (x DDMP on the grid) on 1 and 2 threads: 42
# `bench_mpm --digest 1` runs on a 10-cell block, 10 steps. Two builds whose outputs are equal
# line for line give bit-identical states. Usage: bash bench/mpm/digests.sh BIN_DIR
set -euo pipefail
bin=${1:?usage: digests.sh BIN_DIR}
for shape in linear ugimp cpgimp bspline2 bspline3 ddmp; do
  for scheme in usl musl usf; do
    for threads in 1 2; do
      for on_grid in 0 1; do
        [ "$shape" != ddmp ] && [ "$on_grid" = 1 ] && continue
        digest=$("$bin/bench_mpm" --cells 10 --steps 10 --threads "$threads" --shape "$shape" --scheme "$scheme" \
                   --ddmp-on-grid "$on_grid" --digest 1 2>&1 | grep -io 'digest[^,]*' | head -1)
        echo "$shape $scheme t$threads g$on_grid $digest"
      done
    done
  done
done
