#!/usr/bin/env bash
# Issue 14's error measures of runs against a reference run (docs/tradeoff.md, "Paper
# resolution in minutes"), as latmpm-post computes them (docs/post.md, "Comparing runs"):
# the load (default load_fixed) at every STEP of the reference's travel, each the mean over
# ±STEP/2, its largest difference from the reference's as a fraction of the reference's
# largest (comparison.csv window_load_error, _at); the absorbed energy ∫ F du (metrics.csv
# absorbed_energy) against the reference's (late_error); the largest kinetic over strain
# energy in the second half of the travel (ke_over_se); steps and CPU time from each run's
# status.toml. One CSV row per run on stdout; latmpm-post's files in OUT_DIR.
#   issue14-compare.sh BIN OUT_DIR REF_DIR RUN_DIR... [--load load_fixed] [--step 0.5mm]
set -euo pipefail
bin=$1 out=$2
shift 2
load=load_fixed step=0.5mm runs=()
while [ $# -gt 0 ]; do
  case $1 in
    --load) load=$2; shift 2 ;;
    --step) step=$2; shift 2 ;;
    *) runs+=("$1"); shift ;;
  esac
done
source "$(dirname "$0")/../common/post-metric.sh"
labels=()
for i in "${!runs[@]}"; do labels+=(--label "r$i=${runs[$i]}"); done
"$bin/latmpm-post" "${runs[@]}" "${labels[@]}" -o "$out" --kind compression --load "$load" --reference r0 \
  --window "$step" > /dev/null
status() { sed -n "s/^$1 = //p" "$2/status.toml" | sed 's/^"\(.*\)"$/\1/'; }
ref_cpu=$(status cpu_s "${runs[0]}")
echo "run,steps,cpu_s,cpu_speedup,max_load_error_of_peak,at_mm,energy_J,energy_error,ke_over_se_max_2nd_half,status"
for i in "${!runs[@]}"; do
  run=${runs[$i]} cpu=$(status cpu_s "${runs[$i]}")
  c() { post_comparison "$out/comparison.csv" r0 "r$i" "$1"; }
  printf '%s,%s,%.1f,%.2f,%.4f,%.2f,%.5g,%+.4f,%.2g,%s\n' "$run" "$(status steps "$run")" "$cpu" \
    "$(awk -v r="$ref_cpu" -v c="$cpu" 'BEGIN { print r / c }')" "$(c window_load_error)" "$(c window_load_error_at)" \
    "$(post_metric "$out/metrics.csv" "r$i" absorbed_energy)" "$(c late_error)" "$(c ke_over_se)" "$(status status "$run")"
done
