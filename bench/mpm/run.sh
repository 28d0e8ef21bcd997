#!/usr/bin/env bash
# Solver throughput (docs/benchmarks.md, "Solver core"): particle-updates per second for each
# shape function (DDMP too) on a 512,000-particle elastic block (40³ cells, 2³ points per cell, linear
# elastic, USL, double), with 1 and 2 threads, the peak memory of one run and the machine's
# memory bandwidth (bench_stream).
#   bash bench/mpm/run.sh BIN_DIR [STEPS]
set -euo pipefail
bin_dir=${1:?usage: bench/mpm/run.sh BIN_DIR [STEPS]}
steps=${2:-20}
bench="$bin_dir/bench_mpm"
echo "date: $(date -u +%Y-%m-%dT%H:%MZ)  cpu: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)  cores: $(nproc)"
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
for threads in 1 2; do
  "$bench" --cells 40 --steps "$steps" --threads "$threads"
done
echo "DDMP with MUSL (its scene default), 2 threads:"
"$bench" --cells 40 --steps "$steps" --threads 2 --shape ddmp --scheme musl
echo "peak memory (uGIMP, 2 threads, 5 steps):"
/usr/bin/time -v "$bench" --cells 40 --steps 5 --threads 2 --shape ugimp 2>&1 |
  grep -E "shape|Maximum resident set size" | sed 's/^\s*/  /'
echo "memory bandwidth (STREAM kernels), the ceiling of a memory-bound pass:"
for threads in 1 2; do "$bin_dir/bench_stream" "$threads" | sed 's/^/  /'; done
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
