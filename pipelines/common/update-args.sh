#!/usr/bin/env bash
# Moves FILE.new over FILE only when their contents differ, so that FILE's time changes only
# with its content (a run redone only when its arguments changed). With KEEP = 1, a FILE that
# differs from FILE.new only in the solver's version line ("#solver=...", pipelines/common.mk)
# is kept too: the run made by another build stands (`make <experiment> KEEP_RUNS=1`).
# usage: update-args.sh FILE KEEP
set -euo pipefail
file=$1 keep=${2:-0}
new="$file.new"
if cmp -s "$new" "$file"; then
  rm -f "$new"
elif [ "$keep" = 1 ] && [ -f "$file" ] && cmp -s <(grep -v '^#solver=' "$new") <(grep -v '^#solver=' "$file"); then
  rm -f "$new"
else
  mv "$new" "$file"
fi
