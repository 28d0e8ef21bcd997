#!/usr/bin/env bash
# The QUICK lattice past 10 mm of travel with and without strut-strut grid contact
# (docs/contact.md, "A lattice past 10 mm of travel"): one lattice of `make lattice-compression
# QUICK=1` (2x2x2 cells, 2 mm plates, cell 1 mm, rigid plates, E = 10 MPa, uGIMP) driven to
# TRAVEL, once with one velocity field and once with [contact] over the strut groups of
# `latmpm-voxelize --strut-groups GROUPS` (the printed top plate bonded to the lattice,
# Coulomb mu = FRICTION), one solver thread each; latmpm-post over both.
# usage: contact-study.sh BIN OUT LATTICE PLATEN_Z TRAVEL [GROUPS] [FRICTION]
#   e.g. contact-study.sh build/bin results/contact-study T2P30 21.6667mm 12mm 8 0.3
#   (PLATEN_Z: the lattice's top + h, as in pipelines/lattice-compression/cases-quick.txt)
set -euo pipefail
bin=$1 out=$2 lattice=$3 z=$4 travel=$5 groups=${6:-8} friction=${7:-0.3}
src=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
"$bin/latmpm-lattice" --preset "$lattice" --cells 2x2x2 --plates 2mm --quiet -o "$out/geometry-$lattice.h5"
"$bin/latmpm-voxelize" "$out/geometry-$lattice.h5" --cell 1mm --ppc 2 --strut-groups "$groups" --quiet \
  -o "$out/points-$lattice-g$groups.h5"
common=(--set "points.0.file=$(realpath "$out/points-$lattice-g$groups.h5")" --set grid.cell=1mm --set grid.shape=ugimp
        --set "run.end.plate_displacement=$travel" --set output.series_every=20 --set output.snapshot_every=4000
        --set 'rigid_bodies.base.point=["0mm","0mm","2mm"]'
        --set "rigid_bodies.platen.point=[\"0mm\",\"0mm\",\"$z\"]" --set "bodies.top_plate.trim.point=[\"0mm\",\"0mm\",\"$z\"]")
contact=(--set 'contact.groups=strut_c*' --set contact.bond=lattice,top_plate --set "contact.friction=$friction")
single_run="$out/run-$lattice-single" contact_run="$out/run-$lattice-g$groups-contact"
"$bin/latmpm-solve" "$src/lattice-rigid.toml" "${common[@]}" --threads 1 --quiet -o "$single_run" &
single_pid=$!
"$bin/latmpm-solve" "$src/lattice-rigid.toml" "${common[@]}" "${contact[@]}" --threads 1 --quiet -o "$contact_run"
wait "$single_pid"  # a bare wait returns 0 even when the one-field run failed
"$bin/latmpm-post" "$single_run" "$contact_run" -o "$out/post" --title "QUICK $lattice past 10 mm: one field against strut contact" \
  --kind compression --load load_fixed --fit-range 0.3mm:1mm --label "single=$single_run" --label "contact=$contact_run"
