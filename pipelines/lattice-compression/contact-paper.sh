#!/usr/bin/env bash
# A paper-resolution lattice of `make lattice-compression` (5x5x5 cells, 3 mm plates, cell
# 0.64 mm, rigid plates, uGIMP, 25 mm) rerun with strut-strut grid contact, against the
# pipeline's own one-field run of the same case (docs/contact.md, "At paper resolution"):
# the case's points voxelized again with `--strut-groups GROUPS`, the run made with the
# pipeline run's arguments (RESULTS/run-CASE.args) plus [contact] over the strut groups (the
# printed top plate bonded to the lattice, Coulomb mu = FRICTION), then latmpm-post over both.
# usage: contact-paper.sh BIN CASE OUT [GROUPS] [FRICTION] [THREADS]
#   e.g. contact-paper.sh build/bin T2P30-E10 results/lattice-compression/paper-contact 8 0.3 2
#   (after `make lattice-compression CASES=T2P30-E10`: its geometry, points and run are read)
set -euo pipefail
bin=$1 case=$2 out=$3 groups=${4:-8} friction=${5:-0.3} threads=${6:-2}
results=results/lattice-compression/paper
lattice=${case%%-*}
args_file="$results/run-$case.args"
[[ -f "$args_file" && -f "$results/run-$case/done" ]] ||
  { echo "contact-paper.sh: $args_file: no finished run of $case (make lattice-compression CASES=$case first)" >&2; exit 2; }
mkdir -p "$out"
points="$out/points-$lattice-g$groups.h5"
"$bin/latmpm-voxelize" "$results/geometry-$lattice.h5" --cell 0.64mm --ppc 2 --strut-groups "$groups" --quiet -o "$points"
# The pipeline run's words, one per line, without its solver stamp; its point file swapped
# for the one with strut groups (the same points, tagged).
mapfile -t words < <(grep -v '^#' "$args_file" | sed "s|^points.0.file=.*|points.0.file=$points|")
contact=(--set 'contact.groups=strut_c*' --set contact.bond=lattice,top_plate --set "contact.friction=$friction")
run="$out/run-$case-g$groups"
"$bin/latmpm-solve" "${words[@]}" "${contact[@]}" --threads "$threads" --quiet -o "$run"
"$bin/latmpm-post" "$results/run-$case" "$run" -o "$out/post" --title "$case at paper resolution: one field against strut contact" \
  --kind compression --load load_fixed --fit-range 0.5mm:3mm --label "single=$results/run-$case" --label "contact=$run"
