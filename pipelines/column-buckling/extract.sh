#!/usr/bin/env bash
# The load-displacement curve of one column run: RUN_DIR/series.csv -> OUT.csv with the
# plate's travel in mm and the loads on the driven plate and the fixed base (N, compression
# positive; both from the grid's nodal reactions, see docs/scene.md "Series").
# usage: extract.sh RUN_DIR OUT.csv
set -euo pipefail
run_dir=$1 out=$2
awk -F, '
  NR == 1 {
    for (i = 1; i <= NF; i++) col[$i] = i
    if (!("displacement[m]" in col) || !("load_driven[N]" in col) || !("load_fixed[N]" in col)) {
      print "extract.sh: " FILENAME " lacks displacement[m], load_driven[N] or load_fixed[N]" > "/dev/stderr"
      exit 2
    }
    print "displacement[mm],load_driven[N],load_fixed[N],time[s]"
    next
  }
  { printf "%.6f,%.6g,%.6g,%.6g\n", 1e3 * $col["displacement[m]"], $col["load_driven[N]"], $col["load_fixed[N]"], $col["time[s]"] }
' "$run_dir/series.csv" > "$out.tmp"
mv "$out.tmp" "$out"
