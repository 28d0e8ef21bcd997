# Sourced by tool-level tests: one QUICK lattice case of `make lattice-compression QUICK=1`
# as that experiment runs it. quick_lattice_case BIN_DIR SOURCE_DIR PRESET OUT_DIR [CASE]
# writes the preset's QUICK points (2x2x2 cells, 2 mm plates, cell 1 mm, 2 points per cell per
# direction) to OUT_DIR/points-PRESET.h5, the file the table's rows name (once: an existing
# file is kept), and sets the array `quick_case` to the solver's arguments of the case's row
# (default PRESET-E10; PRESET-E10-ddmp adds DDMP's settings) as the experiment gives them
# (pipelines/common/case-table.sh args), so that the test runs the experiment's own scene.
# Returns non-zero when the table has no such row (case-table.sh names it).
quick_lattice_case() {
  local bin=$1 src=$2 preset=$3 out=$4 case=${5:-$3-E10}
  if [ ! -f "$out/points-$preset.h5" ]; then
    "$bin/latmpm-lattice" --preset "$preset" --cells 2x2x2 --plates 2mm --quiet -o "$out/$preset-geometry.h5"
    "$bin/latmpm-voxelize" "$out/$preset-geometry.h5" --cell 1mm --ppc 2 --quiet -o "$out/points-$preset.h5" 2>/dev/null
  fi
  mapfile -t quick_case < <(bash "$src/pipelines/common/case-table.sh" args \
    "$src/pipelines/lattice-compression/cases-quick.txt" "$case" "$out")
  [ ${#quick_case[@]} -gt 0 ]
}
