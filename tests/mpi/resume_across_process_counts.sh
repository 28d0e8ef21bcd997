#!/usr/bin/env bash
# A run stopped on N MPI processes and resumed on M gives the uninterrupted run's results
# bit for bit (docs/cluster.md, "Checkpoints"): the coarse column run on 2 processes to step
# 80, resumed on 3 processes to step 140, resumed on one process to step 200, against one
# process for 200 steps. The checkpoint of the 2 processes must also be the one a single
# process writes at step 80 (the same state datasets, h5diff).
# usage: resume_across_process_counts.sh BIN_DIR SOURCE_DIR MPI_SOLVE MPIRUN   (empty: skip)
set -euo pipefail
bin_dir=$1 source_dir=$2 mpi_solve=${3:-} mpirun=${4:-}
source "$(dirname "${BASH_SOURCE[0]}")/column_points.sh"
run=("$source_dir/data/scenes/column-tiny.toml" --set points.0.file=c-points.h5 --set output.snapshot_every=40
     --quiet --threads 1)

"$bin_dir/latmpm-solve" "${run[@]}" --set run.max_steps=200 -o whole
"$bin_dir/latmpm-solve" "${run[@]}" --set run.max_steps=80 -o one-at-80
mpi 2 "${run[@]}" --set run.max_steps=80 -o parts
# The checkpoint the 2 processes wrote (each its rows) is the one-process state (the /output
# group holds wall times).
h5diff one-at-80/checkpoint.h5 parts/checkpoint.h5 /state /state
mpi 3 --resume parts --set run.max_steps=140 --quiet --threads 1
grep -q "processes: 3 (MPI)" parts/log.txt
"$bin_dir/latmpm-solve" --resume parts --set run.max_steps=200 --quiet --threads 1
cmp whole/series.csv parts/series.csv
for f in whole/snapshots/snap_*.h5; do
  h5diff "$f" "parts/snapshots/$(basename "$f")" /particles /particles
done
echo "2 processes to step 80, 3 to 140, 1 to 200: series and snapshots equal one process's uninterrupted run, bit for bit"
