#!/usr/bin/env bash
# Keeps the light part of a finished paper-resolution run in the repository, so that the
# comparison documents (docs/paper-a.md and the experiments' summaries) can be rebuilt on any
# checkout without rerunning hours of solver time: results/ is not tracked, records/ is.
# RUN_DIR = results/<experiment>/<mode>/.../run-<case> is recorded as
# records/<experiment>/<mode>/.../run-<case>/ holding `args` (RUN_DIR.args: the solver's
# arguments and the version of the build that ran them), status.toml (how it ended, its cost),
# scene.toml (the resolved scene), log.txt, summary.txt and series.csv.gz: everything
# latmpm-post and pipelines/common/append-runs.sh read. Snapshots and checkpoints are not
# kept (tens to hundreds of MB a run). Only runs whose mode is "paper" or "paper-*" are
# recorded: the QUICK sizes rerun in minutes. pipelines/common/restore-runs.sh puts records
# back under results/.
# usage: record-run.sh RUN_DIR
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
run_dir=${1%/}
rel=$(realpath -m --relative-to="$root/results" "$run_dir")
case $rel in ../* | /*) exit 0 ;; esac  # not under results/
mode=$(cut -d/ -f2 <<< "$rel")  # results/<experiment>/<mode>/...
case $mode in paper | paper-*) ;; *) exit 0 ;; esac
[ -f "$run_dir/done" ] && [ -f "$run_dir/series.csv" ] && [ -f "$run_dir.args" ] || {
  echo "record-run.sh: $run_dir: not a finished run (no done, series.csv or $run_dir.args); not recorded" >&2
  exit 1
}
record="$root/records/$rel"
tmp="$record.tmp.$$"
trap 'rm -rf "$tmp"' EXIT
rm -rf "$tmp"
mkdir -p "$tmp"
cp "$run_dir.args" "$tmp/args"
for f in status.toml scene.toml log.txt summary.txt; do
  if [ -f "$run_dir/$f" ]; then cp "$run_dir/$f" "$tmp/"; fi
done
gzip -9n < "$run_dir/series.csv" > "$tmp/series.csv.gz"
# Replaced whole, never half-written: the new record is complete before the old one goes.
rm -rf "$record"
mv "$tmp" "$record"
echo "record-run.sh: recorded $run_dir in records/$rel" >&2
