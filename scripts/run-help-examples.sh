#!/usr/bin/env bash
# Runs every sample run shown in a tool's --help ("  $ command ...") in a scratch directory,
# with the build's bin/ first on PATH. A tool's manual is thereby also its smoke test.
# usage: run-help-examples.sh BIN_DIR TOOL SOURCE_DIR
set -euo pipefail
bin_dir=$1 tool=$2 source_dir=$3
export PATH="$bin_dir:$PATH" LATMPM_SOURCE_DIR="$source_dir"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cd "$scratch"
examples=$("$tool" --help | sed -n 's/^ *\$ //p')
if [ -z "$examples" ]; then
  echo "$tool --help shows no sample run ('  \$ ...')" >&2
  exit 1
fi
count=0
while IFS= read -r line; do
  echo "+ $line"
  bash -o pipefail -c "$line" </dev/null
  count=$((count + 1))
done <<< "$examples"
echo "$tool: $count sample runs passed"
