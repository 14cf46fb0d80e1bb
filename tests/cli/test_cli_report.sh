#!/bin/sh
# capbridge report --reference DIR with hostile reference files: each is refused before any
# law is measured, exit 1, with one line on stderr naming the file, the line, what is wrong
# and what is allowed. The files are reference_data/cases.csv (the first curves) altered in
# one place. PART "valid" instead runs report on two unaltered curves (it prepares every law,
# the table law too: seconds, minutes under the sanitizers).
# Usage: test_cli_report.sh CAPBRIDGE REFERENCE_DATA_DIR [hostile|valid]
. "$(dirname "$0")/lib.sh"
REF=${2:?"usage: $0 path/to/capbridge path/to/reference_data [hostile|valid]"}
PART=${3:-hostile}
case $PART in hostile | valid) ;; *) echo "$0: part '$PART': allowed hostile, valid" >&2; exit 2 ;; esac
HEADER="case,r1,r2,surface_tension,contact_angle,volume,rupture_distance,point,gap,force,filling_angle1,filling_angle2,pressure,neck_radius"

# the data lines of the first two curves (21 points each) of cases.csv
grep -v '^#' "$REF/cases.csv" | sed -n '2,43p' >"$TMP/rows"
checks=$((checks + 1))
[ "$(sed -n 1p "$REF/cases.csv" | cut -c1-1)" = "#" ] &&
    [ "$(grep -v '^#' "$REF/cases.csv" | sed -n 1p)" = "$HEADER" ] &&
    [ "$(wc -l <"$TMP/rows")" -eq 42 ] || fail "unexpected layout of $REF/cases.csv"
# and the first two sphere-plane curves of plane.csv (r2 written "plane")
grep -v '^#' "$REF/plane.csv" | sed -n '2,43p' >"$TMP/plane_rows"

# expect_refused LABEL NEEDLE... -- CASES_BODY_FILE: cases.csv = header + that body, grid.csv
# the two curves unaltered, plane.csv the two sphere-plane curves
n=0
expect_refused() {
    label=$1
    shift
    n=$((n + 1))
    dir="$TMP/ref$n"
    mkdir "$dir"
    needles=
    while [ "$1" != "--" ]; do
        needles="$needles
$1"
        shift
    done
    { echo "$HEADER"; cat "$2"; } >"$dir/cases.csv"
    { echo "$HEADER"; cat "$TMP/rows"; } >"$dir/grid.csv"
    { echo "$HEADER"; cat "$TMP/plane_rows"; } >"$dir/plane.csv"
    "$CB" report --reference "$dir" >"$TMP/out" 2>"$TMP/err" </dev/null
    code=$?
    checks=$((checks + 1))
    [ "$code" -eq 1 ] || { fail "$label: exit $code, expected 1 ($(head -c 300 "$TMP/err"))"; return; }
    checks=$((checks + 1))
    [ "$(wc -l <"$TMP/err")" -eq 1 ] || fail "$label: stderr is not one line: $(head -c 600 "$TMP/err")"
    checks=$((checks + 1))
    [ ! -s "$TMP/out" ] || fail "$label: printed on stdout: $(head -2 "$TMP/out")"
    printf '%s\n' "$needles" | while IFS= read -r needle; do
        [ -n "$needle" ] || continue
        grep -qF -- "$needle" "$TMP/err" || echo "stderr lacks '$needle': $(cat "$TMP/err")"
    done >"$TMP/why"
    checks=$((checks + 1))
    [ ! -s "$TMP/why" ] || fail "$label: $(cat "$TMP/why")"
}

if [ "$PART" = hostile ]; then
# a curve of point 0 only (the other 20 points were never read)
sed -n 1p "$TMP/rows" >"$TMP/only0"
expect_refused "a curve of point 0 only" "cases.csv:2:" "ends at point 0" "points 0 to 20" -- "$TMP/only0"
# a curve cut short before the next one starts
sed '11,21d' "$TMP/rows" >"$TMP/short"
expect_refused "a curve cut short" "cases.csv:12:" "point 0 of" "points 0 to 20" -- "$TMP/short"
# a point skipped
sed '6d' "$TMP/rows" >"$TMP/skip"
expect_refused "a point skipped" "cases.csv:7:" "point 6" "expected point 5" -- "$TMP/skip"
# header only
: >"$TMP/none"
expect_refused "a header-only file" "cases.csv" "no curves" "at least one" -- "$TMP/none"
# NaN in the first row of a curve (its configuration) and in a later one
sed '1s/^\([^,]*\),[^,]*,/\1,nan,/' "$TMP/rows" >"$TMP/nan0"
expect_refused "a NaN radius" "cases.csv:2:" "r1 'nan'" "a decimal number" -- "$TMP/nan0"
awk -F, -v OFS=, 'NR == 3 { $2 = "nan" } { print }' "$TMP/rows" >"$TMP/nan1"
expect_refused "a NaN radius in a later row" "cases.csv:4:" "r1 'nan'" -- "$TMP/nan1"
# a later row of a curve that is not that curve's configuration
awk -F, -v OFS=, 'NR == 4 { $2 = "2e-3" } { print }' "$TMP/rows" >"$TMP/other"
expect_refused "a row of another configuration" "cases.csv:5:" "r1 differs from line 2" "repeats its configuration" -- "$TMP/other"
# radii, volume, tension, angle out of range
awk -F, -v OFS=, 'NR == 1 { $2 = "-1e-3" } { print }' "$TMP/rows" >"$TMP/negr"
expect_refused "a negative radius" "cases.csv:2:" "r1 = -0.001" "> 0" -- "$TMP/negr"
awk -F, -v OFS=, 'NR == 1 { $5 = "90" } { print }' "$TMP/rows" >"$TMP/theta"
expect_refused "contact angle 90" "cases.csv:2:" "contact_angle = 90" "0 <= contact_angle < 90" -- "$TMP/theta"
awk -F, -v OFS=, 'NR == 5 { $10 = "0" } { print }' "$TMP/rows" >"$TMP/force0"
expect_refused "a zero exact force" "cases.csv:6:" "force = 0" "> 0" -- "$TMP/force0"
# point indices that are not whole numbers in 0..20, 1e300 first of all
for bad in 1e300 -1 21 2.5 nan 1e0; do
    awk -F, -v OFS=, -v p="$bad" 'NR == 3 { $8 = p } { print }' "$TMP/rows" >"$TMP/point"
    expect_refused "point $bad" "cases.csv:4:" "point '$bad'" "a whole number from 0 to 20" -- "$TMP/point"
done
# a wrong number of fields
awk -F, -v OFS=, 'NR == 3 { $15 = "1" } { print }' "$TMP/rows" >"$TMP/fields"
expect_refused "15 fields" "cases.csv:4:" "15 fields" "14" -- "$TMP/fields"
# a line longer than the reader takes (it was split into two rows)
awk -F, -v OFS=, 'NR == 3 { s = "0"; while (length(s) < 2000) s = s "0"; $9 = s $9 } { print }' \
    "$TMP/rows" >"$TMP/longline"
expect_refused "a 2000-character line" "cases.csv:4:" "longer than" -- "$TMP/longline"
# a case name longer than a name holds (it was cut without a word)
awk -F, -v OFS=, '{ $1 = "W" sprintf("%060d", NR <= 21 ? 1 : 2) } { print }' "$TMP/rows" >"$TMP/name"
expect_refused "a 61-character name" "cases.csv:2:" "case name" "characters" -- "$TMP/name"
fi

if [ "$PART" = valid ]; then
# the two curves unaltered are read: richefeu's largest force and rupture-distance errors over
# them, recomputed here from `capbridge force` and `capbridge rupture` at the file's gaps
mkdir "$TMP/good"
{ echo "$HEADER"; cat "$TMP/rows"; } >"$TMP/good/cases.csv"
cp "$TMP/good/cases.csv" "$TMP/good/grid.csv"
{ echo "$HEADER"; cat "$TMP/plane_rows"; } >"$TMP/good/plane.csv"
if "$CB" report --reference "$TMP/good" --csv "$TMP/good/report.csv" >"$TMP/out" 2>"$TMP/err"; then
    awk -F, '$8 == 0 { print $2, $3, $4, $5, $6, $7 }' "$TMP/rows" >"$TMP/configs"
    rupture_max=0
    while read -r r1 r2 gamma theta v d; do
        law=$("$CB" rupture richefeu gamma "$gamma" theta "$theta" --r1 "$r1" --r2 "$r2" --volume "$v" |
            awk -F, 'NR == 2 { print $1 }')
        rupture_max=$(awk -v m="$rupture_max" -v a="$law" -v e="$d" \
            'BEGIN { x = (a - e) / e; if (x < 0) x = -x; printf "%.17g", (x > m ? x : m) }')
    done <"$TMP/configs"
    force_max=0
    awk -F, '$8 < 20 { print $2, $3, $4, $5, $6, $9, $10 }' "$TMP/rows" >"$TMP/points"
    while read -r r1 r2 gamma theta v gap exact; do
        law=$("$CB" force richefeu gamma "$gamma" theta "$theta" --r1 "$r1" --r2 "$r2" --volume "$v" --gap "$gap" |
            awk -F, 'NR == 2 { print $2 }')
        force_max=$(awk -v m="$force_max" -v a="$law" -v e="$exact" \
            'BEGIN { x = (a - e) / e; if (x < 0) x = -x; printf "%.17g", (x > m ? x : m) }')
    done <"$TMP/points"
    # at a plane, the same from the Derjaguin-equivalent pair: two spheres of radius 2 r1
    plane_rupture_max=0
    awk -F, '$8 == 0 { print 2 * $2, $4, $5, $6, $7 }' "$TMP/plane_rows" >"$TMP/plane_configs"
    while read -r r gamma theta v d; do
        law=$("$CB" rupture richefeu gamma "$gamma" theta "$theta" --r1 "$r" --r2 "$r" --volume "$v" |
            awk -F, 'NR == 2 { print $1 }')
        plane_rupture_max=$(awk -v m="$plane_rupture_max" -v a="$law" -v e="$d" \
            'BEGIN { x = (a - e) / e; if (x < 0) x = -x; printf "%.17g", (x > m ? x : m) }')
    done <"$TMP/plane_configs"
    plane_force_max=0
    awk -F, '$8 < 20 { print 2 * $2, $4, $5, $6, $9, $10 }' "$TMP/plane_rows" >"$TMP/plane_points"
    while read -r r gamma theta v gap exact; do
        law=$("$CB" force richefeu gamma "$gamma" theta "$theta" --r1 "$r" --r2 "$r" --volume "$v" --gap "$gap" |
            awk -F, 'NR == 2 { print $2 }')
        plane_force_max=$(awk -v m="$plane_force_max" -v a="$law" -v e="$exact" \
            'BEGIN { x = (a - e) / e; if (x < 0) x = -x; printf "%.17g", (x > m ? x : m) }')
    done <"$TMP/plane_points"
    richefeu=$(awk -F, '$1 == "richefeu"' "$TMP/good/report.csv")
    close_rel "valid curves: richefeu's force error" "$(echo "$richefeu" | cut -d, -f2)" "$force_max" 1e-5
    close_rel "valid curves: richefeu's rupture error" "$(echo "$richefeu" | cut -d, -f6)" "$rupture_max" 1e-5
    close_rel "valid curves: richefeu's sphere-plane force error" "$(echo "$richefeu" | cut -d, -f16)" "$plane_force_max" 1e-5
    close_rel "valid curves: richefeu's sphere-plane rupture error" "$(echo "$richefeu" | cut -d, -f18)" "$plane_rupture_max" 1e-5
    checks=$((checks + 1))
    grep -q "2 cases, 2 grid configurations and 2 sphere-plane ones x 20 gaps" "$TMP/out" || fail "valid curves: $(head -1 "$TMP/out")"
else
    fail "valid curves: exit $? ($(cat "$TMP/err"))"
fi
fi

finish
