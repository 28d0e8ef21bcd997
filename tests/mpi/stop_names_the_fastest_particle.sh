#!/usr/bin/env bash
# A run the energy-balance check stops names the fastest particle of the whole domain, the
# same on N processes as on one: the QUICK T1P20 lattice of `make lattice-compression QUICK=1`
# (rigid half-spaces, the printed base omitted, the top plate trimmed) at cfl 0.5, which
# stops at step ~120 (docs/tradeoff.md, "Time step"). Before 2026-11-27 each process named
# its own fastest particle and rank 0's went into status.toml.
# usage: stop_names_the_fastest_particle.sh BIN_DIR SOURCE_DIR N MPI_SOLVE MPIRUN   (empty: skip)
set -euo pipefail
bin_dir=$1 source_dir=$2 processes=$3 mpi_solve=${4:-} mpirun=${5:-}
source "$(dirname "${BASH_SOURCE[0]}")/column_points.sh"
source "$source_dir/tests/support/quick_lattice_case.sh"
quick_lattice_case "$bin_dir" "$source_dir" T1P20 .
run=("${quick_case[@]}" --set time.cfl=0.5 --set run.max_steps=400 --set output.snapshot_every=100000 --quiet --threads 1)
reason() { sed -n 's/^reason = //p' "$1/status.toml"; }
status=0
"$bin_dir/latmpm-solve" "${run[@]}" -o one 2> one.err || status=$?
[ "$status" = 3 ] || { echo "one process: exit $status, expected 3 (the energy-balance stop)" >&2; cat one.err >&2; exit 1; }
reason one | grep -q "the energy balance is off.*the fastest particle: [0-9]* of body 'lattice'" ||
  { echo "one process: $(reason one)" >&2; exit 1; }
status=0
mpi "$processes" "${run[@]}" -o many 2> many.err || status=$?
[ "$status" = 3 ] || { echo "$processes processes: exit $status, expected 3" >&2; cat many.err >&2; exit 1; }
grep -q "processes: $processes (MPI)" many/log.txt
[ "$(reason one)" = "$(reason many)" ] ||
  { printf 'one process:  %s\n%s processes: %s\n' "$(reason one)" "$processes" "$(reason many)" >&2; exit 1; }
echo "stopped at the same step naming the same particle on $processes processes as on one: $(reason one)"
