#!/usr/bin/env bash
# Before/after throughput of two builds in one run (docs/benchmarks.md, "Solver core"): the
# uGIMP block of run.sh (512,000 particles), 1 and 2 threads, rounds alternating the two
# binaries so that a change of the machine's speed hits both alike. A BIN_DIR is a build's
# bin/ (its libraries in ../lib) or a frozen copy holding bench_mpm and lib/.
#   bash bench/mpm/compare.sh BEFORE_BIN_DIR AFTER_BIN_DIR [ROUNDS] [STEPS] [SHAPE]
set -euo pipefail
before=${1:?usage: bench/mpm/compare.sh BEFORE_BIN_DIR AFTER_BIN_DIR [ROUNDS] [STEPS] [SHAPE]}
after=${2:?usage: bench/mpm/compare.sh BEFORE_BIN_DIR AFTER_BIN_DIR [ROUNDS] [STEPS] [SHAPE]}
rounds=${3:-3} steps=${4:-20} shape=${5:-ugimp}
echo "date: $(date -u +%Y-%m-%dT%H:%MZ)  load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
for r in $(seq "$rounds"); do
  for side in before after; do
    bin=$before; [ "$side" = after ] && bin=$after
    for threads in 1 2; do
      # Each side with its own solver libraries: bench_mpm finds liblatmpm_mpm.so through its
      # build's RUNPATH, so a copied binary would otherwise run the current build's library.
      echo "round $r $side: $(LD_LIBRARY_PATH="$bin/../lib:$bin/lib" "$bin/bench_mpm" --cells 40 --steps "$steps" --threads "$threads" --shape "$shape")"
    done
  done
done
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
