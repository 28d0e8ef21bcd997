#!/usr/bin/env bash
# The impact curves of one run: time[ms], load_flyer[N] (contact force on the flyer),
# load_fixed[N] (base reaction), flyer_speed[m/s] (along the approach, positive down),
# flyer_energy[J] (kinetic + potential, datum at the start), energy_error[J].
# usage: extract.sh RUN_DIR OUT.csv
set -euo pipefail
awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i
                   print "time[ms],load_flyer[N],load_fixed[N],flyer_speed[m/s],flyer_energy[J],energy_error[J]"; next }
         { printf "%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", 1e3 * $col["time[s]"], $col["load_flyer[N]"], $col["load_fixed[N]"],
             $col["flyer_velocity[m/s]"], $col["flyer_kinetic_energy[J]"] + $col["flyer_potential_energy[J]"],
             $col["energy_error[J]"] }' "$1/series.csv" > "$2.tmp"
mv "$2.tmp" "$2"
