# Sourced by pipeline scripts: read one number out of a latmpm-post table instead of
# computing it (docs/post.md: metrics.csv, checks.csv, comparison.csv).
# post_metric FILE LABEL COLUMN: the value in the row whose first cell is LABEL, under the
# header cell COLUMN[unit] (unit left off); empty when the cell is; exit 2 when the table has
# no such column (awk would otherwise print the whole row for an unknown column).
post_metric() {
  awk -F, -v label="$2" -v name="$3" '
    /^#/ { next }
    !h { for (i = 1; i <= NF; i++) { n = $i; sub(/\[.*/, "", n); c[n] = i } h = 1; next }
    !(name in c) { print "post_metric: " FILENAME " has no column " name > "/dev/stderr"; exit 2 }
    $1 == label { print $c[name] }' "$1"
}
# post_comparison FILE REFERENCE LABEL COLUMN: the same from latmpm-post's comparison.csv,
# whose rows are keyed by the reference and the run.
post_comparison() {
  awk -F, -v ref="$2" -v label="$3" -v name="$4" '
    /^#/ { next }
    !h { for (i = 1; i <= NF; i++) { n = $i; sub(/\[.*/, "", n); c[n] = i } h = 1; next }
    !(name in c) { print "post_comparison: " FILENAME " has no column " name > "/dev/stderr"; exit 2 }
    $1 == ref && $2 == label { print $c[name] }' "$1"
}
