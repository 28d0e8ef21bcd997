# Sourced by the tests of this folder: skips (exit 77) without an MPI solver or mpirun, then
# works in a fresh scratch directory holding the coarse column's points (c-points.h5, 544
# points at 0.8 mm: column-tiny.toml's). Needs bin_dir (this build's tools: the one-process
# solver every result is compared with), mpi_solve (the MPI latmpm-solve) and mpirun set.
if [ -z "$mpirun" ] || [ -z "$mpi_solve" ]; then
  echo "skipped: no MPI solver (cmake -DLATMPM_MPI_TESTS=ON with mpiexec installed, or make mpi)"
  exit 77
fi
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cd "$scratch"
"$bin_dir/latmpm-lattice" --column --diameter 1.6mm --length 16mm --end-plates 0.8mm -o c.h5 >/dev/null
"$bin_dir/latmpm-voxelize" c.h5 --cell 0.8mm --ppc 2 -o c-points.h5 >/dev/null
# Oversubscribed on a small machine: yield instead of spinning while waiting. A process
# left waiting for another ends in the timeout (exit 124), not in ctest's.
mpi() { timeout 300 "$mpirun" -np "$1" --oversubscribe --mca mpi_yield_when_idle 1 "$mpi_solve" "${@:2}"; }
