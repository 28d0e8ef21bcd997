#!/usr/bin/env bash
# The impact curves of one run: time[ms], load_flyer[N] (contact force on the flyer),
# load_fixed[N] (base reaction), flyer_speed[m/s] (along the approach, positive down),
# flyer_energy[J] (kinetic + potential, datum at the start), energy_error[J].
# The flyer's curves are latmpm-post's (POST_CURVE = its curves/<label>.load_time.csv, which
# sums the flyer's energy, docs/post.md); the base reaction and the energy error are copied
# from the run's series.csv beside them, row for row.
# usage: extract.sh RUN_DIR POST_CURVE OUT.csv
set -euo pipefail
run=$1 curve=$2 out=$3
paste -d, <(grep -v '^#' "$curve") "$run/series.csv" |
  awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if (!($i in col)) col[$i] = i
                     print "time[ms],load_flyer[N],load_fixed[N],flyer_speed[m/s],flyer_energy[J],energy_error[J]"; next }
           { printf "%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", $col["time[ms]"], $col["load_flyer[N]"], $col["load_fixed[N]"],
               $col["flyer_velocity[m/s]"], $col["flyer_energy[J]"], $col["energy_error[J]"] }' > "$out.tmp"
mv "$out.tmp" "$out"
