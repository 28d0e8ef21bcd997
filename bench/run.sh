#!/usr/bin/env bash
# Runs every benchmark script bench/*/run.sh with the build's bin/ directory. Results are
# printed; docs/benchmarks.md records them with the command and date.
set -euo pipefail
bin_dir=${1:?usage: bench/run.sh BIN_DIR}
here=$(cd "$(dirname "$0")" && pwd)
for script in "$here"/*/run.sh; do
  [ -f "$script" ] || continue
  echo "== $(basename "$(dirname "$script")")"
  bash "$script" "$bin_dir"
done
