#!/usr/bin/env bash
# Geometric rigid bodies on several MPI processes give the one-process results bit for bit
# (docs/cluster.md, "Rigid bodies", "Penalty contact"): the column of
# column-platen-contact.toml against one process, 150 steps each, with its platen (1)
# coupled through the grid, no-slip, (2) replaced by a free flyer (an impact, paper A Sec. 6:
# a 50 g box at 2 m/s, no-slip), (3) in penalty contact as the scene has it (stick), and
# (4) the flyer in penalty contact with friction 0.1; on 2 processes, and (3) on 4 too.
# series.csv byte for byte (loads, reactions, contact energies, the flyer's motion), the
# last snapshot's particles and the final checkpoint's state (h5diff).
# usage: rigid_bodies_on_processes.sh BIN_DIR SOURCE_DIR MPI_SOLVE MPIRUN   (empty: skip)
set -euo pipefail
bin_dir=$1 source_dir=$2 mpi_solve=${3:-} mpirun=${4:-}
source "$(dirname "${BASH_SOURCE[0]}")/column_points.sh"
scene=("$source_dir/data/scenes/column-platen-contact.toml" --set points.0.file=c-points.h5 --set run.max_steps=150
       --set output.snapshot_every=150 --quiet --threads 1)
flyer='{ motion = "free", shape = "box", mass = "0.05kg", min = ["-5mm", "-5mm", "17.6mm"], max = ["5mm", "5mm", "27.6mm"], velocity = ["0m/s", "0m/s", "-2m/s"]'
overrides_no_slip=(--set 'rigid_bodies.platen.contact={ model = "no_slip" }')
overrides_flyer=(--set "rigid_bodies.platen=$flyer }" --set 'run.end={ time = "1ms" }')
overrides_penalty=()
overrides_penalty_flyer=(--set "rigid_bodies.platen=$flyer, contact = { model = \"penalty\", friction = 0.1 } }"
                         --set 'run.end={ time = "1ms" }')
for v in no_slip:2 flyer:2 penalty:2 penalty:4 penalty_flyer:2; do
  name=${v%:*} processes=${v#*:}
  declare -n extra="overrides_$name"
  [ -d "$name-one" ] || "$bin_dir/latmpm-solve" "${scene[@]}" "${extra[@]}" -o "$name-one"
  mpi "$processes" "${scene[@]}" "${extra[@]}" -o "$name-$processes"
  grep -q "processes: $processes (MPI)" "$name-$processes/log.txt"
  cmp "$name-one/series.csv" "$name-$processes/series.csv"
  h5diff "$name-one/snapshots/snap_000150.h5" "$name-$processes/snapshots/snap_000150.h5" /particles /particles
  # The final checkpoint, every process's rows of it (with penalty contact's optional fields).
  h5diff "$name-one/checkpoint.h5" "$name-$processes/checkpoint.h5" /state /state
  echo "$name: $processes processes equal one, bit for bit"
done
