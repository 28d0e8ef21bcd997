#!/usr/bin/env bash
# The elastic lattice's permanent set against the solver's settings (docs/paper-b.md, "The
# elastic lattice's permanent set"): one T2P30 cell (11.73 mm, 1064 points at 1 mm and 2 points
# per cell per direction), neo-Hookean Ti-6Al-4V, frictionless platens, the metal-lattice
# scene (pipelines/metal-lattice/ti-lattice.toml) with its schedule scaled to 2.8 mm of travel
# (24 %) and back; one setting changed a row. Per row: the strain energy at its peak and at the
# end (the lattice unloaded and free), the kinetic energy at the end, the lattice's height
# change (lattice_height.py) and what of the points' strain their positions show
# (strain_compatibility.py, interior points).
# The last rows filter F's null space (grid.null_space_filter, docs/solver.md "Null-space filter").
#   usage: lattice_set_study.sh BIN_DIR OUT_DIR [ROWS]   (~3 min of CPU; writes OUT_DIR/table.md)
#   ROWS: an extended regular expression; only the rows whose setting matches it run.
set -euo pipefail
bin=${1:?usage: lattice_set_study.sh BIN_DIR OUT_DIR [ROWS]}
out=${2:?usage: lattice_set_study.sh BIN_DIR OUT_DIR [ROWS]}
select=${3:-}
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/../.." && pwd)
mkdir -p "$out"
"$bin/latmpm-lattice" --preset T2P30 --cells 1x1x1 --no-plates --quiet -o "$out/cell.h5"
for ppc in 2 3 4; do
  "$bin/latmpm-voxelize" "$out/cell.h5" --cell 1mm --ppc $ppc --quiet -o "$out/points-$ppc.h5"
done
"$bin/latmpm-voxelize" "$out/cell.h5" --cell 0.5mm --ppc 2 --quiet -o "$out/points-h0.5.h5"

# The schedule of ti-lattice.toml for d = 2.8 mm at 16 m/s: t1 = 175 us, deepest at 195 us,
# t2 = 2 t1 + 20 us + 0.5 mm / v = 401.25 us, 50 us at rest.
cell=(rigid_bodies.platen.point='["0mm","0mm","11.7333mm"]' run.end.time=471.25us
      rigid_bodies.platen.schedule.2.time=175us rigid_bodies.platen.schedule.3.time=215us
      rigid_bodies.platen.schedule.4.time=401.25us rigid_bodies.platen.schedule.5.time=421.25us
      rigid_bodies.platen.contact.friction=0 rigid_bodies.base.contact.friction=0
      'bodies.lattice.material={model="neo_hookean",E="113.8GPa",nu=0.342,density="4430kg/m^3"}'
      output.snapshot_every=100000 checkpoint.every_steps=200)
# The same at 4 m/s (t1 = 700 us, t2 = 1545 us).
slow=(rigid_bodies.platen.schedule.1.velocity='["0m/s","0m/s","-4m/s"]'
      rigid_bodies.platen.schedule.2.velocity='["0m/s","0m/s","-4m/s"]'
      rigid_bodies.platen.schedule.3.velocity='["0m/s","0m/s","4m/s"]'
      rigid_bodies.platen.schedule.4.velocity='["0m/s","0m/s","4m/s"]'
      rigid_bodies.platen.schedule.2.time=700us rigid_bodies.platen.schedule.3.time=740us
      rigid_bodies.platen.schedule.4.time=1545us rigid_bodies.platen.schedule.5.time=1565us run.end.time=1615us)
stiff=rigid_bodies.platen.contact.stiffness
soft=rigid_bodies.base.contact.stiffness
rows=(
  "scene as it is (uGIMP, USL, flip 0.99, cfl 0.5)|2|"
  "flip 0 (PIC)|2|grid.flip=0"
  "flip 1 (FLIP)|2|grid.flip=1"
  "MUSL|2|grid.scheme=musl"
  "cfl 0.25|2|time.cfl=0.25"
  "cfl 0.1|2|time.cfl=0.1"
  "4 m/s instead of 16|2|${slow[*]}"
  "contact stiffness 1e8 N/m (default ~2.2e7)|2|$stiff=1e8N/m $soft=1e8N/m"
  "contact stiffness 5e6 N/m|2|$stiff=5e6N/m $soft=5e6N/m"
  "contact reach = point|2|rigid_bodies.platen.contact.reach=point rigid_bodies.base.contact.reach=point"
  "cpGIMP|2|grid.shape=cpgimp"
  "DDMP|2|grid.shape=ddmp"
  "3 points per cell per direction|3|"
  "4 points per cell per direction|4|"
  "grid 0.5 mm (2 points per cell), 4 m/s|h0.5|grid.cell=0.5mm ${slow[*]}"
  "null-space filter on F, every step|2|grid.null_space_filter=deformation"
  "null-space filter on F, every 10 steps|2|grid.null_space_filter=deformation grid.null_space_filter_every=10"
  "null-space filter on F, every 100 steps|2|grid.null_space_filter=deformation grid.null_space_filter_every=100"
)
{
  echo "| setting (one T2P30 cell, elastic, frictionless, 2.8 mm and back) | strain energy: peak, end (J) | end / peak | kinetic at the end (J) | height change (mm) | interior: mean \|E(F)\|, \|E(G)\|, \|E(F)\| over the block | interior energy of F, of G (J) | CPU (s) |"
  echo "|---|---|---|---|---|---|---|---|"
} > "$out/table.md"
set -f  # the overrides hold [ ] (no globbing)
n=0
for row in "${rows[@]}"; do
  IFS='|' read -r label points overrides <<< "$row"
  n=$((n + 1))
  if [ -n "$select" ] && ! grep -Eq -- "$select" <<< "$label"; then continue; fi
  run="$out/run-$n"
  sets=()
  for s in "${cell[@]}" $overrides; do sets+=(--set "$s"); done
  case $points in h0.5) spacing=0.25 ;; *) spacing=$(python3 -c "print(1 / $points)") ;; esac
  /usr/bin/time -f %U -o "$run.cpu" "$bin/latmpm-solve" "$repo/pipelines/metal-lattice/ti-lattice.toml" \
    --set points.0.file="$out/points-$points.h5" "${sets[@]}" -o "$run" --quiet 2> "$run.log" \
    || { echo "| $label | failed: $(tail -1 "$run.log") |" >> "$out/table.md"; continue; }
  energies=$(python3 - "$run/series.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
se = [float(r["strain_energy[J]"]) for r in rows]
end = rows[-1]
print(f"{max(se):.2f}, {se[-1]:.3f} | {se[-1] / max(se):.1%} | {float(end['kinetic_energy[J]']):.4f}")
PY
)
  height=$(python3 - "$repo/pipelines/metal-lattice" "$run" <<'PY'
import sys
sys.path.insert(0, sys.argv[1])
from lattice_height import final_height_change
h = final_height_change(sys.argv[2])
print("—" if h is None else f"{h['change_m'] * 1e3:+.3f}")
PY
)
  compat=$(python3 "$here/strain_compatibility.py" "$run" --spacing "$spacing" | python3 -c "
import re, sys
t = sys.stdin.read()
v = lambda k: re.search(re.escape(k) + r' ([0-9.e+-]+)', t).group(1)
print(f\"{v('mean |E(F)|')}, {v('mean |E(G)|')}, {v('averaged over the block|')} | {v('energy of F')}, {v('energy of G')}\")")
  echo "| $label | $energies | $height | $compat | $(cat "$run.cpu") |" >> "$out/table.md"
done
cat "$out/table.md"
