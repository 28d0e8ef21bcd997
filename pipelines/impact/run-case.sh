#!/usr/bin/env bash
# One impact case: puts the flyer's lower face on the top plate of the case's lattice (read
# from the lattice file's /geometry/plates), writes RUN_DIR.args and runs
# pipelines/common/solve-case.sh.
# usage: run-case.sh BIN_DIR RUN_DIR THREADS LATTICE.h5 -- SCENE OVERRIDES...
set -euo pipefail
bin=$1 run_dir=$2 threads=$3 lattice=$4
shift 5
# Row 1 of /geometry/plates/boxes (after the two dimension lines and row 0) = xmin ymin zmin
# xmax ymax zmax of the top plate, m: its 6th value is the top face.
top=$(h5dump -d /geometry/plates/boxes -y -w 0 "$lattice" | tr -s ' ,' '\n' | grep -E '^-?[0-9.]+(e-?[0-9]+)?$' | sed -n 16p)
[ -n "$top" ] || { echo "run-case.sh: no top plate in $lattice" >&2; exit 2; }
top_mm=$(awk -v z="$top" 'BEGIN { printf "%.6f", z * 1e3 }')
high_mm=$(awk -v z="$top" 'BEGIN { printf "%.6f", z * 1e3 + 20 }')
{ printf '%s\n' "$@"
  printf '%s\n' --set "rigid_bodies.flyer.min=[\"-100mm\",\"-100mm\",\"${top_mm}mm\"]" \
                --set "rigid_bodies.flyer.max=[\"100mm\",\"100mm\",\"${high_mm}mm\"]"; } > "$run_dir.args"
bash pipelines/common/solve-case.sh "$bin" "$run_dir" "$threads"
