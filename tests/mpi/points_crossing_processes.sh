#!/usr/bin/env bash
# Points that change process (migration) keep the one-process results bit for bit
# (docs/cluster.md, "Migration"): the coarse column without its plates falls under a
# sideways gravity, some 4 cells down and 2 across in 120 steps, so its points leave their
# buckets, are re-sorted about every 20 steps, enter empty buckets and buckets of other
# processes. On 3 processes, and on 2 processes stopped at step 60 and resumed on 3,
# against one process: series.csv byte for byte, every snapshot's particles (h5diff), and
# the log must show migration bytes.
# usage: points_crossing_processes.sh BIN_DIR SOURCE_DIR MPI_SOLVE MPIRUN   (empty: skip)
set -euo pipefail
bin_dir=$1 mpi_solve=${3:-} mpirun=${4:-}
source "$(dirname "${BASH_SOURCE[0]}")/column_points.sh"
cat > falling.toml <<'EOF'
# The column of column-tiny.toml, plates omitted, falling sideways: a uniform acceleration
# of (8, 4, -12)·10^4 m/s² moves it some (2, 1, -3) mm in 120 steps.
[run]
end = { time = "10ms" }
max_steps = 120
[grid]
cell = "0.8mm"
shape = "ugimp"
scheme = "usl"
[time]
cfl = 0.3
mass_scaling = 6
[gravity]
g = ["80000m/s^2", "40000m/s^2", "-120000m/s^2"]
[[points]]
file = "c-points.h5"
[bodies.column]
role = "deformable"
material = { model = "linear_elastic", E = "10MPa", nu = 0.4, density = "1050kg/m^3" }
[bodies.bottom_plate]
role = "omitted"
[bodies.top_plate]
role = "omitted"
[output]
series_every = 10
snapshot_every = 60
record_tag = ""              # the points tagged "record" lie in the omitted plates
EOF
"$bin_dir/latmpm-solve" falling.toml --quiet --threads 1 -o one
mpi 3 falling.toml --quiet --threads 1 -o three
mpi 2 falling.toml --set run.max_steps=60 --quiet --threads 1 -o resumed
mpi 3 --resume resumed --set run.max_steps=120 --quiet --threads 1
for run in three resumed; do
  # The last "processes:" line: the part of the run on 3 processes.
  migration=$(grep -o "[0-9.e+]* migration bytes" "$run/log.txt" | tail -1 | cut -d' ' -f1)
  echo "$run: $migration migration bytes per process and step"
  awk -v m="$migration" 'BEGIN { exit !(m > 0) }' || { echo "$run: no point changed process" >&2; exit 1; }
  cmp one/series.csv "$run/series.csv"
  for f in one/snapshots/snap_*.h5; do
    h5diff "$f" "$run/snapshots/$(basename "$f")" /particles /particles
  done
done
echo "points crossing processes (3; 2 then 3): series and snapshots equal one process's, bit for bit"
