#!/usr/bin/env bash
# Puts recorded runs (records/, written by pipelines/common/record-run.sh) back under
# results/ as finished run directories: RUN_DIR.args, RUN_DIR/args.used, the recorded files,
# series.csv, and the stamp RUN_DIR/done. A run directory that already exists is left alone
# (a run made here is never overwritten). The restored runs carry the version of the build
# that made them, so a pipeline redoes them unless asked to keep them: `make <experiment>
# KEEP_RUNS=1` (pipelines/common.mk) keeps every run whose arguments, the solver's version
# aside, are the case table's.
# usage: restore-runs.sh [RECORD_DIR...]   (default: every record under records/)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$root"
if [ $# -eq 0 ]; then
  [ -d records ] || { echo "restore-runs.sh: no records/ directory" >&2; exit 0; }
  mapfile -t records < <(find records -type f -name args -printf '%h\n' | sort)
else
  records=("$@")
fi
restored=0 kept=0
for record in "${records[@]}"; do
  record=${record%/}
  rel=${record#records/}
  [ "$rel" != "$record" ] && [ -f "$record/args" ] && [ -f "$record/series.csv.gz" ] || {
    echo "restore-runs.sh: $record: not a record (records/<...>/run-<case>/ with args and series.csv.gz)" >&2
    exit 2
  }
  run_dir="results/$rel"
  if [ -e "$run_dir" ]; then
    kept=$((kept + 1))
    continue
  fi
  tmp="$run_dir.restoring.$$"
  mkdir -p "$tmp"
  # The record's files as record-run.sh kept them, the series unpacked and args as args.used.
  for f in "$record"/*; do
    case ${f##*/} in
    args) cp "$f" "$tmp/args.used" ;;
    series.csv.gz) gzip -dc "$f" > "$tmp/series.csv" ;;
    *) cp "$f" "$tmp/" ;;
    esac
  done
  cp "$record/args" "$run_dir.args"
  mv "$tmp" "$run_dir"
  touch "$run_dir/done"
  restored=$((restored + 1))
done
echo "restore-runs.sh: $restored runs restored under results/, $kept already there (left alone)" >&2
