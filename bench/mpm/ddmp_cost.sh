#!/usr/bin/env bash
# DDMP's cost against uGIMP's per particle-update (issue 15's ≤ 1.5×), two builds side by side,
# rounds alternating the builds: the benchmark cube (bench_mpm, 24³ cells, 110,592 points,
# 20 steps) and a lattice scene (latmpm-solve on a pipeline's RUN.args with grid.shape set),
# one solver thread, CPU seconds. The lattice's figure is CPU(20 + STEPS steps) − CPU(20 steps),
# which leaves out reading the points and setting up. A BIN_DIR is a build's bin/ (its
# libraries in ../lib) or a frozen copy holding bench_mpm, latmpm-solve and lib/.
#   bash bench/mpm/ddmp_cost.sh BEFORE_BIN_DIR AFTER_BIN_DIR [ROUNDS] [LATTICE_ARGS] [STEPS]
# LATTICE_ARGS default: the QUICK T2P30-E10 row (`make QUICK=1 CASES=T2P30-E10
# results/lattice-compression/quick/run-T2P30-E10.args`); the paper-size row is
# results/lattice-compression/paper/run-T2P30-E10.args (`make CASES=T2P30-E10 …`). STEPS: 500.
set -euo pipefail
usage="usage: bench/mpm/ddmp_cost.sh BEFORE_BIN_DIR AFTER_BIN_DIR [ROUNDS] [LATTICE_ARGS] [STEPS]"
before=${1:?$usage} after=${2:?$usage}
rounds=${3:-3} lattice_args=${4:-results/lattice-compression/quick/run-T2P30-E10.args} steps=${5:-500}
mapfile -t args < <(grep -v '^#' "$lattice_args")
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
lattice_cpu() {  # BIN SHAPE STEPS: CPU seconds of the run
  LD_LIBRARY_PATH="$1/../lib:$1/lib" "$1/latmpm-solve" "${args[@]}" --set grid.shape="$2" --set run.max_steps="$3" \
    --set output.snapshot_every=1000000 --threads 1 --quiet -o "$out/run" > /dev/null
  sed -n 's/^cpu_s = //p' "$out/run/status.toml"
}
echo "date: $(date -u +%Y-%m-%dT%H:%MZ)  load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "lattice: $lattice_args, $steps steps"
echo "round side shape cube_cpu_s lattice_cpu_s"
for r in $(seq "$rounds"); do
  for side in before after; do
    bin=$before; [ "$side" = after ] && bin=$after
    for shape in ugimp ddmp; do
      cube=$(LD_LIBRARY_PATH="$bin/../lib:$bin/lib" "$bin/bench_mpm" --cells 24 --steps 20 --threads 1 --shape "$shape" |
             sed -n 's/.*(cpu \([0-9.]*\) s).*/\1/p')
      set_up=$(lattice_cpu "$bin" "$shape" 20)
      whole=$(lattice_cpu "$bin" "$shape" $((20 + steps)))
      echo "$r $side $shape $cube $(awk -v a="$whole" -v b="$set_up" 'BEGIN { printf "%.3f", a - b }')"
    done
  done
done
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
