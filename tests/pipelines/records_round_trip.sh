#!/usr/bin/env bash
# A paper-resolution run is recorded in records/ when it finishes (pipelines/common/
# record-run.sh, from solve-case.sh), and put back by restore-runs.sh as a run that
# latmpm-post reads exactly as the original: the same series, the same metrics. A QUICK run
# is not recorded; an existing run directory is never overwritten; KEEP_RUNS keeps a run
# whose arguments differ from the table's only in the solver's version (update-args.sh).
# The scripts are copied into a scratch repository root, so records/ and results/ are
# written there, not in the source tree.
# usage: records_round_trip.sh BIN_DIR SOURCE_DIR
set -euo pipefail
bin=$1 src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAILED: $*"; exit 1; }
mkdir -p "$work/pipelines/common"
cp "$src"/pipelines/common/*.sh "$work/pipelines/common/"
cd "$work"
"$bin/latmpm-lattice" --column --diameter 1.6mm --length 16mm --end-plates 0.8mm --quiet -o c.h5
"$bin/latmpm-voxelize" c.h5 --cell 0.8mm --ppc 2 --quiet -o c-points.h5 2>/dev/null
# One case as a pipeline writes it: RUN.args, one word a line, the solver's version last.
case_args() {
  mkdir -p "$(dirname "$1")"
  printf '%s\n' "$src/data/scenes/column-tiny.toml" --set "points.0.file=$work/c-points.h5" \
    --set run.end.plate_displacement=0.2mm "#solver=$2" > "$1.args"
}
paper=results/column-buckling/paper/run-tiny quick=results/column-buckling/quick/run-tiny
case_args "$paper" build-a
case_args "$quick" build-a
bash pipelines/common/solve-case.sh "$bin" "$paper" 1 2> solve.err || { cat solve.err; fail "the paper case did not run"; }
bash pipelines/common/solve-case.sh "$bin" "$quick" 1 2>> solve.err || { cat solve.err; fail "the quick case did not run"; }
record=records/column-buckling/paper/run-tiny
for f in args status.toml scene.toml log.txt series.csv.gz; do
  [ -f "$record/$f" ] || fail "the paper run's record lacks $f"
done
cmp -s "$record/args" "$paper.args" || fail "the record's args are not the run's"
[ ! -e records/column-buckling/quick ] || fail "a QUICK run was recorded"
# The mode is the directory under the experiment's: an experiment named paper-* is not a mode.
case_args results/paper-x/quick/run-tiny build-a
mkdir -p results/paper-x/quick/run-tiny && cp "$quick"/{series.csv,status.toml} results/paper-x/quick/run-tiny/
touch results/paper-x/quick/run-tiny/done
bash pipelines/common/record-run.sh results/paper-x/quick/run-tiny
[ ! -e records/paper-x ] || fail "a QUICK run of an experiment named paper-x was recorded"
echo "recorded: $(ls "$record" | tr '\n' ' ')"

"$bin/latmpm-post" "$paper" -o post-original --kind column --label tiny="$paper" > /dev/null
mv results results-original
bash pipelines/common/restore-runs.sh 2> restore.err || { cat restore.err; fail "restore-runs.sh failed"; }
[ -f "$paper/done" ] || fail "the restored run has no stamp"
cmp -s "$paper/series.csv" "results-original/column-buckling/paper/run-tiny/series.csv" || fail "the restored series differs"
cmp -s "$paper.args" "$record/args" || fail "the restored RUN.args is not the record's"
[ ! -e "$quick" ] || fail "a QUICK run was restored"
"$bin/latmpm-post" "$paper" -o post-restored --kind column --label tiny="$paper" > /dev/null
# The provenance lines (#: the time, the command's output directory) differ by design.
cmp -s <(grep -v '^#' post-original/metrics.csv) <(grep -v '^#' post-restored/metrics.csv) || {
  diff post-original/metrics.csv post-restored/metrics.csv
  fail "latmpm-post reads the restored run differently"
}
echo "restored: latmpm-post's metrics.csv identical ($(grep -vc '^#' post-restored/metrics.csv) rows)"

# A run directory that exists is left alone.
echo "made here" > "$paper/marker"
bash pipelines/common/restore-runs.sh 2> restore.err
[ -f "$paper/marker" ] || fail "restore-runs.sh overwrote an existing run"
grep -q "0 runs restored" restore.err || fail "restore-runs.sh: $(cat restore.err)"

# update-args.sh: another build's arguments replace the file unless KEEP = 1; other changes always do.
cp "$paper.args" kept.args
case_args other build-b && mv other.args kept.args.new
bash pipelines/common/update-args.sh kept.args 1
grep -q '^#solver=build-a$' kept.args || fail "KEEP_RUNS=1 replaced a run of another build"
case_args other build-b && mv other.args kept.args.new
bash pipelines/common/update-args.sh kept.args 0
grep -q '^#solver=build-b$' kept.args || fail "without KEEP_RUNS a run of another build stood"
case_args other build-b && sed 's/0.2mm/0.3mm/' other.args > kept.args.new
bash pipelines/common/update-args.sh kept.args 1
grep -q '0.3mm' kept.args || fail "KEEP_RUNS=1 kept a run whose arguments changed"
echo "update-args.sh: KEEP = 1 keeps another build's run, not changed arguments"
