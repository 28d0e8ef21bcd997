#!/usr/bin/env bash
# Cantilever under its own weight: tip deflection / beam theory against cell size for
# uGIMP, DDMP and linear MPM (issue 15; docs/solver.md, "DDMP in bending"). Runs the hidden
# Catch2 case `test_mpm "[cantilever-study]"` (tests/mpm/test_cantilever.cpp: t = 4 mm,
# L = 8 t, 2, 4 and 8 cells across) and writes OUT_DIR/cantilever-study.csv and the plot
# OUT_DIR/cantilever-study.png (error |w/w_beam − 1| against cells across, log–log).
#   bash bench/mpm/cantilever_study.sh BIN_DIR OUT_DIR
set -euo pipefail
bin_dir=${1:?usage: bench/mpm/cantilever_study.sh BIN_DIR OUT_DIR}
out_dir=${2:?usage: bench/mpm/cantilever_study.sh BIN_DIR OUT_DIR}
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out_dir"
log="$out_dir/cantilever-study.log"
"$bin_dir/test_mpm" "[cantilever-study]" > "$log"
# Lines "cantilever SHAPE across N measured W m reference R m ratio Q".
awk 'BEGIN { print "shape,cells_across,measured[m],reference[m],ratio" }
     $1 == "cantilever" { print $2 "," $4 "," $6 "," $9 "," $12 }' "$log" > "$out_dir/cantilever-study.csv"
if [ "$(wc -l < "$out_dir/cantilever-study.csv")" -lt 2 ]; then
  echo "cantilever_study.sh: no result lines in $log" >&2
  exit 4
fi
gnuplot -e "csv='$out_dir/cantilever-study.csv'; png='$out_dir/cantilever-study.png'" "$here/plot_cantilever_study.gp"
echo "cantilever_study.sh: $out_dir/cantilever-study.csv, $out_dir/cantilever-study.png"
