# Sourced by tool-level tests: one QUICK lattice case of `make lattice-compression QUICK=1`
# as that experiment runs it. quick_lattice_case BIN_DIR SOURCE_DIR PRESET OUT_DIR writes the
# preset's QUICK points (2x2x2 cells, 2 mm plates, cell 1 mm, 2 points per cell per
# direction) to OUT_DIR/PRESET.h5 (once: an existing file is kept) and sets the array
# `quick_case` to the solver's arguments: the rigid-plate scene, the point file, the cell, and
# the overrides of the table's `*` row and of the case's row (default PRESET-E10: planes,
# modulus, shape; PRESET-E10-ddmp adds DDMP's settings), read from cases-quick.txt so that the
# test runs the experiment's own scene. Exit 1 when the table has no such row.
# usage: quick_lattice_case BIN_DIR SOURCE_DIR PRESET OUT_DIR [CASE]
quick_lattice_case() {
  local bin=$1 src=$2 preset=$3 out=$4 case=${5:-$3-E10}
  local table=$src/pipelines/lattice-compression/cases-quick.txt word
  if [ ! -f "$out/$preset.h5" ]; then
    "$bin/latmpm-lattice" --preset "$preset" --cells 2x2x2 --plates 2mm --quiet -o "$out/$preset-geometry.h5"
    "$bin/latmpm-voxelize" "$out/$preset-geometry.h5" --cell 1mm --ppc 2 --quiet -o "$out/$preset.h5" 2>/dev/null
  fi
  quick_case=("$src/pipelines/lattice-compression/lattice-rigid.toml" --set "points.0.file=$out/$preset.h5")
  local -a words
  mapfile -t words < <(grep -E "^(\*|$case) " "$table" | awk '{ for (i = 4; i <= NF; i++) print $i }')
  grep -q "^$case " "$table" && [ ${#words[@]} -gt 0 ] || { echo "no $case row in $table" >&2; return 1; }
  for word in "${words[@]}"; do quick_case+=(--set "$word"); done
}
