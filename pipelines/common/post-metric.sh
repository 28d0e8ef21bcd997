# Sourced by pipeline scripts: read one number out of a latmpm-post table instead of
# computing it (docs/post.md: metrics.csv, checks.csv, comparison.csv).
# post_metric FILE LABEL COLUMN: the value in the row whose first cell is LABEL, under the
# header cell COLUMN[unit] (unit left off); empty when the cell is.
post_metric() {
  awk -F, -v label="$2" -v name="$3" '
    /^#/ { next }
    !h { for (i = 1; i <= NF; i++) { n = $i; sub(/\[.*/, "", n); c[n] = i } h = 1; next }
    $1 == label { print $c[name] }' "$1"
}
