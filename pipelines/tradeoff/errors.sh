#!/usr/bin/env bash
# Error of one run against a reference run, from their series.csv (docs/scene.md "Series"):
#   curve   relative L2 difference of the load-displacement curves, both averaged over 50 bins
#           of the reference's travel (removes the explicit solver's step-to-step ripple):
#           sqrt(sum (F_run - F_ref)^2 / sum F_ref^2) over the bins
#   peak    (peak load of the run - peak of the reference) / peak of the reference
#   late    column: post-buckling load (mean over the last quarter of the travel) against the
#           reference's; lattice: work W = int F du (trapezoid rule) against the reference's
#   euler   column only: post-buckling load / Euler load - 1 (EULER_N > 0)
#   ke_se   largest kinetic / strain energy ratio over the second half of the travel: the
#           quasi-static check (small when the run is quasi-static)
# Prints one CSV line: curve,peak,late,euler,ke_se (euler empty when EULER_N is 0).
# usage: errors.sh REF_RUN RUN KIND EULER_N   (KIND: column or lattice)
set -euo pipefail
ref=$1 run=$2 kind=$3 euler=$4
awk -F, -v kind="$kind" -v euler="$euler" -v nb=50 '
  FNR == 1 {
    file++
    delete col
    for (i = 1; i <= NF; i++) col[$i] = i
    cu = col["displacement[m]"]; cf = col["load_driven[N]"]
    ck = col["kinetic_energy[J]"]; cs = col["strain_energy[J]"]
    if (!cu || !cf || !ck || !cs) { print "errors.sh: " FILENAME ": missing columns" > "/dev/stderr"; exit 2 }
    next
  }
  { n[file]++; u[file, n[file]] = $cu; f[file, n[file]] = $cf; k[file, n[file]] = $ck; s[file, n[file]] = $cs }
  END {
    travel = u[1, n[1]]
    for (r = 1; r <= 2; r++) {
      peak[r] = -1e300; late_sum = 0; late_n = 0; work[r] = 0; kese[r] = 0
      for (i = 1; i <= n[r]; i++) {
        if (f[r, i] > peak[r]) peak[r] = f[r, i]
        b = int(u[r, i] / travel * nb); if (b >= nb) b = nb - 1
        if (u[r, i] <= travel) { bsum[r, b] += f[r, i]; bcnt[r, b]++ }
        if (u[r, i] >= 0.75 * u[r, n[r]]) { late_sum += f[r, i]; late_n++ }
        if (i > 1) work[r] += 0.5 * (f[r, i] + f[r, i - 1]) * (u[r, i] - u[r, i - 1])
        if (u[r, i] >= 0.5 * u[r, n[r]] && s[r, i] > 0 && k[r, i] / s[r, i] > kese[r]) kese[r] = k[r, i] / s[r, i]
      }
      post[r] = late_n ? late_sum / late_n : 0
    }
    d2 = 0; r2 = 0
    for (b = 0; b < nb; b++) {
      if (!bcnt[1, b] || !bcnt[2, b]) continue
      fr = bsum[1, b] / bcnt[1, b]; fx = bsum[2, b] / bcnt[2, b]
      d2 += (fx - fr) ^ 2; r2 += fr ^ 2
    }
    curve = r2 > 0 ? sqrt(d2 / r2) : 0
    late = kind == "column" ? post[2] / post[1] - 1 : work[2] / work[1] - 1
    e = euler > 0 ? sprintf("%.4f", post[2] / euler - 1) : ""
    printf "%.4f,%.4f,%.4f,%s,%.4g\n", curve, peak[2] / peak[1] - 1, late, e, kese[2]
  }' "$ref/series.csv" "$run/series.csv"
