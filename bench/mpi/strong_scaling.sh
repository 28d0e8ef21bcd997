#!/usr/bin/env bash
# Strong scaling of the solver on one host (issue 21; docs/cluster.md, "Strong scaling"):
# T2P30-E10 at paper A's resolution (rigid plates, 0.64 mm, uGIMP, 532,817 points; the run of
# docs/experiments.md, "one paper-resolution run") on 1 thread, 2 threads (the shared-memory
# solver) and 2 MPI processes of one thread each, alternating (t1, t2, r2, t1, t2, r2, …).
# Each configuration runs WARMUP steps and WARMUP + STEPS steps; the difference over STEPS is
# the time per step without the start-up (reading the points, building, the first sort, the
# final checkpoint). Prints the medians of wall and CPU (user + system) seconds per step, the
# speed-ups, the halo the MPI runs sent per process and step (their log's last line), and
# checks that the three give the same series.csv byte for byte.
#
# For an idle machine: it stops starting rounds when the next would pass BUDGET seconds of
# wall since the start (default 540: the whole script within 10 min on 2 idle cores, the
# points made once and kept in WORK). On a loaded machine the figures are the scheduler's.
#
# usage: bench/mpi/strong_scaling.sh [WORK]   (from the repository root, after `make` and
#        `cmake --build build --target latmpm_mpi_solver`, or `make mpi`)
# environment: BIN (build/bin), MPI_SOLVE (build/mpi/bin/latmpm-solve, else build-mpi/bin/…),
#        STEPS (200), WARMUP (20), ROUNDS (5, at most), BUDGET (540 s), CELL (0.64mm; a
#        coarser cell for a quick check of the script: CELL=1.28mm STEPS=4 WARMUP=2 ROUNDS=1)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
work=${1:-strong-scaling}
bin=${BIN:-$root/build/bin}
mpi_solve=${MPI_SOLVE:-$root/build/mpi/bin/latmpm-solve}
[ -x "$mpi_solve" ] || mpi_solve=$root/build-mpi/bin/latmpm-solve
steps=${STEPS:-200} warmup=${WARMUP:-20} rounds=${ROUNDS:-5} budget=${BUDGET:-540} cell=${CELL:-0.64mm}
for tool in "$bin/latmpm-lattice" "$bin/latmpm-voxelize" "$bin/latmpm-solve" "$mpi_solve"; do
  [ -x "$tool" ] || { echo "strong_scaling: $tool not built" >&2; exit 1; }
done
command -v mpirun >/dev/null || { echo "strong_scaling: mpirun not found (openmpi-bin)" >&2; exit 1; }
[ -x /usr/bin/time ] || { echo "strong_scaling: /usr/bin/time not found (Debian package time)" >&2; exit 1; }
# As root (containers) OpenMPI wants these; its single-copy transport can fail in containers.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl_vader_single_copy_mechanism=none
mkdir -p "$work"
cd "$work"
start=$(date +%s)
echo "host: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"

# The specimen (made once, kept): T2P30, 5×5×5 cells, 3 mm plates, 2 points per cell and axis.
points=pts-${cell}.h5
if [ ! -f "$points" ]; then
  "$bin/latmpm-lattice" --preset T2P30 --cells 5x5x5 --plates 3mm --quiet -o geo.h5
  "$bin/latmpm-voxelize" geo.h5 --cell "$cell" --ppc 2 --quiet -o "$points"
fi
scene=(pipelines/lattice-compression/lattice-rigid.toml --set "points.0.file=$PWD/$points"
       --set "grid.cell=$cell" --set run.end.plate_displacement=20mm --set output.series_every=10
       --set output.snapshot_every=0 --set 'rigid_bodies.base.point=["0mm","0mm","3mm"]' --set grid.shape=ugimp
       --set bodies.lattice.material.E=10MPa --set bodies.top_plate.material.E=10MPa
       --set 'rigid_bodies.platen.point=["0mm","0mm","50.3067mm"]'
       --set 'bodies.top_plate.trim.point=["0mm","0mm","50.3067mm"]' --quiet)

# run CONFIG N: N steps of CONFIG (t1, t2, r2) into run-CONFIG-N; prints "wall cpu".
run() {
  local config=$1 n=$2 out=$PWD/run-$1-$2
  local solve=("$bin/latmpm-solve") threads=1
  case $config in
    t2) threads=2 ;;
    r2) solve=(mpirun -np 2 --mca mpi_yield_when_idle 1 "$mpi_solve") ;;
  esac
  rm -rf "$out"
  (cd "$root" && /usr/bin/time -f "%e %U %S" -o "$out.time" "${solve[@]}" "${scene[@]}" --set "run.max_steps=$n" \
     --threads "$threads" -o "$out") >/dev/null
  awk '{printf "%.3f %.3f\n", $1, $2 + $3}' "$out.time"
}

declare -A wall cpu
last_round=0
for ((r = 1; r <= rounds; ++r)); do
  elapsed=$(( $(date +%s) - start ))
  if [ "$r" -gt 1 ] && [ $((elapsed + last_round)) -gt "$budget" ]; then
    echo "round $r not started: ${elapsed} s gone, a round takes ${last_round} s (BUDGET=$budget)"
    break
  fi
  round_start=$(date +%s)
  for config in t1 t2 r2; do
    # Not through a process substitution: set -e must see a run that fails.
    run "$config" "$warmup" > times.txt
    read -r w0 c0 < times.txt
    run "$config" $((warmup + steps)) > times.txt
    read -r w1 c1 < times.txt
    wall[$config]+="$(awk -v a="$w0" -v b="$w1" -v s="$steps" 'BEGIN{printf "%.5f", (b - a) / s}') "
    cpu[$config]+="$(awk -v a="$c0" -v b="$c1" -v s="$steps" 'BEGIN{printf "%.5f", (b - a) / s}') "
  done
  last_round=$(( $(date +%s) - round_start ))
  echo "round $r: ${last_round} s; load average $(cut -d' ' -f1-3 /proc/loadavg)"
done

median() { tr ' ' '\n' | grep -v '^$' | sort -g | awk '{v[NR]=$1} END{if (NR % 2) print v[(NR+1)/2]; else printf "%.5f\n", (v[NR/2] + v[NR/2+1]) / 2}'; }
long=$((warmup + steps))
echo
points_run=$(grep -o '(deformable): [0-9]* points' "run-t1-$long/log.txt" | awk '{n += $2} END {print n}')
echo "T2P30-E10, cell $cell, $points_run points, $steps steps (runs of $long minus runs of $warmup), medians of the rounds:"
printf "%-28s %12s %12s   %s\n" "" "wall s/step" "CPU s/step" "(each round: wall; CPU)"
declare -A label=([t1]="1 thread" [t2]="2 threads (TBB)" [r2]="2 MPI processes × 1 thread")
declare -A median_wall
for config in t1 t2 r2; do
  median_wall[$config]=$(echo "${wall[$config]}" | median)
  printf "%-28s %12s %12s   (%s; %s)\n" "${label[$config]}" "${median_wall[$config]}" "$(echo "${cpu[$config]}" | median)" \
    "${wall[$config]% }" "${cpu[$config]% }"
done
awk -v a="${median_wall[t1]}" -v b="${median_wall[t2]}" -v c="${median_wall[r2]}" \
  'BEGIN{printf "wall speed-up over 1 thread: 2 threads %.2f, 2 processes %.2f\n", a / b, a / c}'
echo "halo (MPI, $long steps): $(grep -o 'processes: [0-9]* to [0-9]* particles each.*' "run-r2-$long/log.txt")"
cmp "run-t1-$long/series.csv" "run-t2-$long/series.csv"
cmp "run-t1-$long/series.csv" "run-r2-$long/series.csv"
echo "series.csv of the three equal byte for byte; whole script $(( $(date +%s) - start )) s; load average at end: $(cut -d' ' -f1-3 /proc/loadavg)"
