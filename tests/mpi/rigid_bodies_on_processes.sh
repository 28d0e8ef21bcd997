#!/usr/bin/env bash
# Geometric rigid bodies on several MPI processes give the one-process results bit for bit
# (docs/cluster.md, "Rigid bodies"): the column of column-platen-contact.toml on 2 processes
# against one, 150 steps each, with its platen (1) coupled through the grid, no-slip, and
# (2) replaced by a free flyer (an impact, paper A Sec. 6: a 50 g box at 2 m/s, no-slip).
# series.csv byte for byte (loads, reactions, the flyer's motion) and the last snapshot's
# particles (h5diff). Penalty contact (the scene as it is) is refused on 2 processes (exit 2).
# usage: rigid_bodies_on_processes.sh BIN_DIR SOURCE_DIR MPI_SOLVE MPIRUN   (empty: skip)
set -euo pipefail
bin_dir=$1 source_dir=$2 mpi_solve=${3:-} mpirun=${4:-}
source "$(dirname "${BASH_SOURCE[0]}")/column_points.sh"
scene=("$source_dir/data/scenes/column-platen-contact.toml" --set points.0.file=c-points.h5 --set run.max_steps=150
       --set output.snapshot_every=150 --quiet --threads 1)
flyer='{ motion = "free", shape = "box", mass = "0.05kg", min = ["-5mm", "-5mm", "17.6mm"], max = ["5mm", "5mm", "27.6mm"], velocity = ["0m/s", "0m/s", "-2m/s"] }'
variants=(no_slip flyer)
overrides_no_slip=(--set 'rigid_bodies.platen.contact={ model = "no_slip" }')
overrides_flyer=(--set "rigid_bodies.platen=$flyer" --set 'run.end={ time = "1ms" }')
for v in "${variants[@]}"; do
  declare -n extra="overrides_$v"
  "$bin_dir/latmpm-solve" "${scene[@]}" "${extra[@]}" -o "$v-one"
  mpi 2 "${scene[@]}" "${extra[@]}" -o "$v-two"
  grep -q "processes: 2 (MPI)" "$v-two/log.txt"
  cmp "$v-one/series.csv" "$v-two/series.csv"
  h5diff "$v-one/snapshots/snap_000150.h5" "$v-two/snapshots/snap_000150.h5" /particles /particles
  echo "$v: 2 processes equal one, bit for bit"
done
status=0
mpi 2 "${scene[@]}" -o penalty 2> penalty.err || status=$?
[ "$status" = 2 ] || { echo "penalty contact on 2 processes: exit $status, expected 2" >&2; exit 1; }
grep -q "rigid_bodies.platen.*contact.*penalty contact does not run on several MPI processes" penalty.err
echo "penalty contact: refused on 2 processes (exit 2)"
