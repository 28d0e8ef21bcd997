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
scenes=$source_dir/pipelines/lattice-compression
"$bin_dir/latmpm-lattice" --preset T1P20 --cells 2x2x2 --plates 2mm --quiet -o t1p20.h5
"$bin_dir/latmpm-voxelize" t1p20.h5 --cell 1mm --ppc 2 --quiet -o t1p20-points.h5 2>/dev/null
mapfile -t row < <(grep "^T1P20-E10 " "$scenes/cases-quick.txt" | tr ' ' '\n' | grep '=')
base=$(sed -n 's/^\*.*\(rigid_bodies\.base\.point=[^ ]*\).*/\1/p' "$scenes/cases-quick.txt")
[ ${#row[@]} -gt 0 ] && [ -n "$base" ] || { echo "no T1P20-E10 row in $scenes/cases-quick.txt" >&2; exit 1; }
run=("$scenes/lattice-rigid.toml" --set points.0.file=t1p20-points.h5 --set grid.cell=1mm --set "$base")
for word in "${row[@]}"; do run+=(--set "$word"); done
run+=(--set time.cfl=0.5 --set run.max_steps=400 --set output.snapshot_every=100000 --quiet --threads 1)
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
