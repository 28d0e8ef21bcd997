#!/usr/bin/env bash
# Runs the coarse column (data/scenes/column-tiny.toml) on one process and on N MPI
# processes and requires the same series.csv byte for byte, the same particles in every
# snapshot (positions in double precision) and the same checkpoint state, both files written
# by every process at once (parallel HDF5): the MPI domain keeps the one-process sums'
# order (docs/cluster.md), so nothing may differ, not even in the last bit.
# usage: same_as_one_process.sh BIN_DIR SOURCE_DIR N MPI_SOLVE MPIRUN   (empty: no MPI, skip)
set -euo pipefail
bin_dir=$1 source_dir=$2 processes=$3 mpi_solve=${4:-} mpirun=${5:-}
source "$(dirname "${BASH_SOURCE[0]}")/column_points.sh"
# 200 steps (the plate travels 0.08 mm), snapshots at steps 0, 100 and 200: the
# decomposition, the halo exchange, the ordered sums and the shared snapshots. No point
# changes process here (the log's migration bytes are 0): migration is not exercised. Short: on a loaded 2-core machine every one of the step's
# collective calls waits for a time slice (measured 0.44 s per step on 2 processes at load 20).
run=("$source_dir/data/scenes/column-tiny.toml" --set points.0.file=c-points.h5 --set run.max_steps=200
     --set output.snapshot_every=100 --quiet --threads 1)
"$bin_dir/latmpm-solve" "${run[@]}" -o one
mpi "$processes" "${run[@]}" -o many
grep -q "processes: $processes (MPI)" many/log.txt
# Every process held particles: the halo exchange and the ordered sums were exercised.
shares=$(grep -o "processes: [0-9]* to [0-9]* particles each.*" many/log.txt)
echo "$shares"
fewest=$(echo "$shares" | sed 's/processes: \([0-9]*\) to.*/\1/')
[ "$fewest" -gt 0 ] || { echo "a process held no particles" >&2; exit 1; }
cmp one/series.csv many/series.csv
for f in one/snapshots/snap_*.h5; do
  h5diff "$f" "many/snapshots/$(basename "$f")" /particles /particles
done
cmp one/snapshots.xmf many/snapshots.xmf  # the XDMF series ParaView opens
# The checkpoint at the last step (run.max_steps): every process wrote its rows of it.
h5diff one/checkpoint.h5 many/checkpoint.h5 /state /state
echo "series, snapshots and checkpoint of $processes processes equal one process's, bit for bit"
# ... into one file at once: the MPI solver links the parallel HDF5 and only it.
grep -q "every process its rows of each snapshot and checkpoint (parallel HDF5" many/log.txt
hdf5_libraries=$(ldd "$mpi_solve" | grep -o 'libhdf5[a-z_]*\.so' | sort -u | tr '\n' ' ')
[ "$hdf5_libraries" = "libhdf5_openmpi.so " ] || { echo "the MPI solver links: $hdf5_libraries" >&2; exit 1; }
# A file rank 0 cannot write (here the snapshot folder, a plain file) while the others wait
# in a collective: every process stops with exit 2 and the file named, none is left waiting
# (MpiSession: MPI_Abort with the status; a hang ends in mpi's timeout, exit 124).
mkdir blocked && touch blocked/snapshots
status=0
mpi "$processes" "${run[@]}" -o blocked 2> blocked.err || status=$?
[ "$status" = 2 ] || { echo "rank 0 unable to write: exit $status, expected 2" >&2; cat blocked.err >&2; exit 1; }
grep -q "blocked/snapshots: cannot create the snapshot directory" blocked.err
echo "rank 0 unable to write its snapshots: all $processes processes stopped, exit 2"
# What the MPI solver cannot do is refused at set-up, with exit 2 and the key named, before
# any step: the null-space filter (one solve over a whole body).
status=0
mpi "$processes" "${run[@]}" --set grid.null_space_filter=deformation \
  --set 'bodies.column.material={model="neo_hookean",E="10MPa",nu=0.4,density="1050kg/m^3"}' -o filtered 2> filtered.err || status=$?
[ "$status" = 2 ] || { echo "null-space filter on $processes processes: exit $status, expected 2" >&2; cat filtered.err >&2; exit 1; }
grep -q "grid.null_space_filter.*does not run on several MPI processes" filtered.err || { cat filtered.err >&2; exit 1; }
[ ! -e filtered ] || { echo "the refused run wrote its run directory" >&2; exit 1; }
echo "the null-space filter on $processes processes: refused at set-up, exit 2"
