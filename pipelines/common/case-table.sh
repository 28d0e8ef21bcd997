#!/usr/bin/env bash
# Reads an experiment's case table (pipelines/<experiment>/cases-{quick,paper}.txt): one row
# per run, whitespace-separated columns
#   case     points         scene          overrides...
# - case: the run's name (run directory OUT_DIR/run-<case>);
# - points: the point file (points.0.file), relative to OUT_DIR; or "run:DIR", a run made
#   elsewhere that this table's summary reuses (DIR relative to OUT_DIR; no run is made);
# - scene: the scene file, relative to the table's directory;
# - overrides: KEY=VALUE words, each given to latmpm-solve as --set KEY=VALUE (no spaces
#   inside a value: TOML arrays are written ["0mm","0mm","-100mm/s"]).
# A row named "*" holds defaults: its points and scene stand for "-" in the rows below it,
# and its overrides come before each row's own (the later --set of a key wins). '#' starts a
# comment.
#
# usage: case-table.sh list TABLE SHAPES     rows "case|points|scene" (scene "-" for a
#                                            reused run), leaving out rows whose grid.shape
#                                            is not among SHAPES (comma-separated)
#        case-table.sh args TABLE CASE OUT_DIR   the solver's arguments of CASE, one a line:
#                                            the scene, then --set and KEY=VALUE
set -euo pipefail
command=$1 table=$2
[ -f "$table" ] || { echo "case-table.sh: $table: no such case table" >&2; exit 2; }
case $command in
list) awk_mode=list; shapes=$3; wanted="" out="" ;;
args) awk_mode=args; shapes=""; wanted=$3 out=$4 ;;
*) echo "usage: case-table.sh list TABLE SHAPES | args TABLE CASE OUT_DIR" >&2; exit 1 ;;
esac
awk -v mode="$awk_mode" -v shapes="$shapes" -v wanted="$wanted" -v out="$out" -v table="$table" '
  function fail(message) { printf "%s:%d: %s\n", table, FNR, message > "/dev/stderr"; failed = 1; exit 2 }
  # A path relative to the directory of the table, as seen from the repository root.
  function beside_table(path,   dir) {
    if (path == "" || path ~ /^\//) return path
    dir = table; if (!sub(/\/[^\/]*$/, "", dir)) dir = "."
    path = dir "/" path
    while (sub(/[^\/.][^\/]*\/\.\.\//, "", path)) {}
    return path
  }
  { sub(/#.*/, "") }
  NF == 0 { next }
  NF < 3 { fail("a row needs at least case, points and scene") }
  $1 == "*" {
    default_points = $2 == "-" ? "" : $2; default_scene = $3 == "-" ? "" : beside_table($3); default_sets = ""
    for (i = 4; i <= NF; i++) default_sets = default_sets " " $i
    next
  }
  {
    name = $1; points = $2 == "-" ? default_points : $2; scene = $3 == "-" ? default_scene : beside_table($3)
    if (name in seen) fail("case " name " appears twice")
    seen[name] = 1
    sets = default_sets
    for (i = 4; i <= NF; i++) sets = sets " " $i
    n = split(sets, word, " ")
    for (i = 1; i <= n; i++) if (word[i] !~ /^[A-Za-z0-9_.]+=/) fail("\"" word[i] "\" is not KEY=VALUE")
    reused = points ~ /^run:/
    if (points == "" || (!reused && scene == "")) fail("case " name ": no points or scene (and no \"*\" row above)")
    if (mode == "list") {
      shape = "ugimp"  # the scenes default
      for (i = 1; i <= n; i++) if (word[i] ~ /^grid\.shape=/) shape = substr(word[i], 12)
      if (("," shapes ",") !~ ("," shape ",")) next
      print name "|" points "|" (reused ? "-" : scene)
    } else if (name == wanted) {
      if (reused) fail("case " name " reuses " substr(points, 5) ": it is not run from this table")
      print scene
      print "--set"; print "points.0.file=" out "/" points
      for (i = 1; i <= n; i++) { print "--set"; print word[i] }
      found = 1
    }
  }
  END {
    if (failed) exit 2
    if (mode == "args" && !found) { printf "%s: no case %s\n", table, wanted > "/dev/stderr"; exit 2 }
  }' "$table"
