#!/bin/sh
# capbridge replay: a table built from the CLI's own `force` output with one perturbed
# row; the same rows as a CSV file and as a LAMMPS `dump local` file (centre distances);
# malformed rows named with their line; --tolerance.
. "$(dirname "$0")/lib.sh"

PERTURBATION=1e-3 # relative, on the force of data row 4
# r1 r2 volume gap (volume 0: no bridge)
cat >"$TMP/pairs" <<'PAIRS'
1e-3 1e-3 1e-11 0
1e-3 5e-4 1e-11 2e-5
5e-4 2e-3 3e-12 1e-5
1e-3 1e-3 1e-11 5e-5
2e-3 2e-3 2e-11 -1e-6
1e-3 1e-3 1e-11 3e-4
1e-3 1e-3 0 1e-5
PAIRS

printf 'id r1 r2 volume gap force\n' >"$TMP/table.txt"
printf '# written by test_cli_replay.sh\nid,r1,r2,volume,gap,force\n' >"$TMP/table.csv"
row=0
while read -r r1 r2 v gap; do
    row=$((row + 1))
    if [ "$v" = 0 ]; then
        f=0
    else
        f=$("$CB" force richefeu --r1 "$r1" --r2 "$r2" --volume "$v" --gap "$gap" | awk -F, 'NR == 2 { print $2 }')
    fi
    [ "$row" -eq 4 ] && f=$(awk -v f="$f" -v p="$PERTURBATION" 'BEGIN { printf "%.17g", f * (1 + p) }')
    printf '%d %s %s %s %s %s\n' "$row" "$r1" "$r2" "$v" "$gap" "$f" >>"$TMP/table.txt"
    printf '%d, %s,%s,%s,%s,%s\n' "$row" "$r1" "$r2" "$v" "$gap" "$f" >>"$TMP/table.csv"
done <"$TMP/pairs"

expected_rel=$(awk -v p="$PERTURBATION" 'BEGIN { printf "%.17g", p / (1 + p) }')
HEADER="rows,bridges,max_relative_difference,row,line,file_force,law_force,max_absolute_difference"
COLUMNS=r1=2,r2=3,volume=4,gap=5,force=6

# expect_report LABEL FILE ROWS BRIDGES REL ROW LINE TOLERANCE [replay arguments...]
expect_report() {
    label=$1 file=$2 rows=$3 bridges=$4 rel=$5 row=$6 line=$7 tol=$8
    shift 8
    if ! "$CB" replay richefeu "$@" "$file" >"$TMP/out" 2>"$TMP/err"; then
        fail "$label: exit status $? ($(cat "$TMP/err"))"
        return
    fi
    checks=$((checks + 1))
    [ "$(sed -n 1p "$TMP/out")" = "$HEADER" ] || fail "$label: header $(sed -n 1p "$TMP/out")"
    close_rel "$label: rows" "$(field "$TMP/out" 2 1)" "$rows" 0
    close_rel "$label: bridges" "$(field "$TMP/out" 2 2)" "$bridges" 0
    close_rel "$label: largest relative difference" "$(field "$TMP/out" 2 3)" "$rel" "$tol"
    close_rel "$label: its row" "$(field "$TMP/out" 2 4)" "$row" 0
    close_rel "$label: its line" "$(field "$TMP/out" 2 5)" "$line" 0
}

# the rows are the CLI's own numbers (printed to 17 digits): only row 4 differs
expect_report "whitespace table" "$TMP/table.txt" 7 6 "$expected_rel" 4 5 1e-9 --columns "$COLUMNS"
expect_report "CSV with a comment" "$TMP/table.csv" 7 6 "$expected_rel" 4 6 1e-9 --columns "$COLUMNS"
abs=$(awk 'NR == 5 { f = $6; printf "%.17g", f - f / 1.001 }' "$TMP/table.txt")
close_rel "whitespace table: largest absolute difference" \
    "$("$CB" replay richefeu --columns "$COLUMNS" "$TMP/table.txt" | field /dev/stdin 2 8)" "$abs" 1e-6
# columns in another order, radii and volume as constants, standard input
awk 'NR > 1 && $2 == "1e-3" && $3 == "1e-3" && $4 == "1e-11" { print $6, $5 }' "$TMP/table.txt" >"$TMP/two"
"$CB" replay richefeu --columns force=1,gap=2 --r1 1e-3 --r2 1e-3 --volume 1e-11 - <"$TMP/two" >"$TMP/out" ||
    fail "constants from options: exit $?"
close_rel "constants from options: rows" "$(field "$TMP/out" 2 1)" 3 0
close_rel "constants from options: difference" "$(field "$TMP/out" 2 3)" "$expected_rel" 1e-9
close_rel "constants from options: row" "$(field "$TMP/out" 2 4)" 2 0

# a LAMMPS dump local with two snapshots and centre distances (gap = distance - r1 - r2)
awk 'NR == 1 { next }
     { n++; line[n] = sprintf("%d %d %s %s %s %.17g %s", $1, $1 + 1, $2, $3, $4, $5 + ($2 + $3), $6) }
     END {
        for (t = 0; t <= 100; t += 100) {
            print "ITEM: TIMESTEP"; print t
            print "ITEM: NUMBER OF ENTRIES"; print n
            print "ITEM: BOX BOUNDS pp pp pp"; print "-0.01 0.01"; print "-0.01 0.01"; print "-0.01 0.01"
            print "ITEM: ENTRIES c_pair[1] c_pair[2] c_pair[3] c_pair[4] c_pair[5] c_pair[6] c_pair[7]"
            for (i = 1; i <= n; i++) print line[i]
        }
     }' "$TMP/table.txt" >"$TMP/dump.local"
# the distance loses digits of the gap: the unperturbed rows differ by round-off only
expect_report "dump local" "$TMP/dump.local" 14 12 "$expected_rel" 4 13 1e-9 \
    --columns r1=3,r2=4,volume=5,distance=6,force=7

# --tolerance
"$CB" replay richefeu --columns "$COLUMNS" --tolerance 1e-2 "$TMP/table.txt" >/dev/null 2>&1
close_rel "--tolerance 1e-2 passes" "$?" 0 0
"$CB" replay richefeu --columns "$COLUMNS" --tolerance 1e-6 "$TMP/table.txt" >/dev/null 2>"$TMP/err"
close_rel "--tolerance 1e-6 fails" "$?" 1 0
checks=$((checks + 1))
grep -q "row 4, line 5" "$TMP/err" || fail "--tolerance message: $(cat "$TMP/err")"

# malformed rows: exit 1, each named with its line and the reason
# expect_malformed LABEL FILE NEEDLE [replay arguments]
expect_malformed() {
    label=$1 file=$2 needle=$3
    shift 3
    "$CB" replay richefeu "$@" "$file" >"$TMP/out" 2>"$TMP/err"
    code=$?
    checks=$((checks + 1))
    [ "$code" -eq 1 ] || fail "$label: exit $code, expected 1"
    checks=$((checks + 1))
    grep -qF -- "$needle" "$TMP/err" || fail "$label: stderr lacks '$needle': $(cat "$TMP/err")"
}
sed '4s/ 3e-12 / abc /' "$TMP/table.txt" >"$TMP/bad1"
expect_malformed "a word in a number column" "$TMP/bad1" "bad1:4: column 4 (volume) is 'abc', not a decimal number within double range" --columns "$COLUMNS"
sed '6s/ [^ ]*$//' "$TMP/table.txt" >"$TMP/bad2"
expect_malformed "a short row" "$TMP/bad2" "bad2:6: 5 fields, but column 6 (force) is needed" --columns "$COLUMNS"
sed '4s/,2e-5,/,nan,/' "$TMP/table.csv" >"$TMP/bad3"
expect_malformed "nan in a CSV" "$TMP/bad3" "bad3:4: column 5 (gap) is 'nan'" --columns "$COLUMNS"
sed '4s/,2e-5,/,,/' "$TMP/table.csv" >"$TMP/bad4"
expect_malformed "an empty CSV field" "$TMP/bad4" "bad4:4: column 5 (gap) is ''" --columns "$COLUMNS"
sed '2s/^1 1e-3/1 -1e-3/' "$TMP/table.txt" >"$TMP/bad5"
expect_malformed "a negative radius" "$TMP/bad5" "bad5:2: r1 = -0.001: a radius must be > 0" --columns "$COLUMNS"
awk 'NR == 14 { next } { print }' "$TMP/dump.local" >"$TMP/bad6"
expect_malformed "a dump section shorter than announced" "$TMP/bad6" \
    "bad6:9: ITEM: NUMBER OF ENTRIES (line 4) announced 7 rows, this ENTRIES section has 6" \
    --columns r1=3,r2=4,volume=5,distance=6,force=7
: >"$TMP/empty"
expect_malformed "no data rows" "$TMP/empty" "no data rows" --columns "$COLUMNS"
expect_malformed "a missing file" "$TMP/does-not-exist" "cannot open" --columns "$COLUMNS"


# ITEM: NUMBER OF ENTRIES must be a whole number in digits that a long holds: a count of
# 1e30 or 2^63 - 1 before one row was taken as a whole dump (exit 0; (long)1e30 undefined)
# expect_count LABEL COUNT NEEDLE...: a dump announcing COUNT with one row after it
expect_count() {
    label=$1 count=$2
    shift 2
    printf 'ITEM: TIMESTEP\n0\nITEM: NUMBER OF ENTRIES\n%s\nITEM: ENTRIES c1 c2 c3 c4 c5\n%s\n' \
        "$count" "1e-3 1e-3 1e-11 0 0" >"$TMP/count.dump"
    "$CB" replay richefeu --columns r1=1,r2=2,volume=3,gap=4,force=5 "$TMP/count.dump" \
        >"$TMP/out" 2>"$TMP/err"
    code=$?
    checks=$((checks + 1))
    [ "$code" -eq 1 ] || fail "$label: exit $code, expected 1 ($(cat "$TMP/err"))"
    for needle in "$@"; do
        checks=$((checks + 1))
        grep -qF -- "$needle" "$TMP/err" || fail "$label: stderr lacks '$needle': $(cat "$TMP/err")"
    done
}
ALLOWED="allowed a whole number from 0 to 9223372036854775807, in digits"
expect_count "a count of 1e30" 1e30 "count.dump:4: ITEM: NUMBER OF ENTRIES: '1e30' is not a count" "$ALLOWED"
expect_count "a count of 2^63" 9223372036854775808 "'9223372036854775808' is not a count" "$ALLOWED"
expect_count "a count of -1" -1 "'-1' is not a count" "$ALLOWED"
expect_count "a count of +1" +1 "'+1' is not a count" "$ALLOWED"
expect_count "a count of 1.0" 1.0 "'1.0' is not a count" "$ALLOWED"
expect_count "a count of 2^63 - 1" 9223372036854775807 \
    "count.dump:5: ITEM: NUMBER OF ENTRIES (line 4) announced 9223372036854775807 rows, this ENTRIES section has 1"
expect_count "a count of 2" 2 "announced 2 rows, this ENTRIES section has 1"

# a NUL byte in a line: that line is refused by its number, the next one is read on its own
# (it was merged into the line of the NUL)
{
    printf 'r1 r2 volume gap force\n'
    sed -n 2p "$TMP/table.txt" | cut -d' ' -f2-
    printf '1e-3 1e-3\0001e-11 0 0\n'
    sed -n 3,4p "$TMP/table.txt" | cut -d' ' -f2-
} >"$TMP/nul"
"$CB" replay richefeu --columns r1=1,r2=2,volume=3,gap=4,force=5 "$TMP/nul" >"$TMP/out" 2>"$TMP/err"
close_rel "a NUL byte: exit status" "$?" 1 0
close_rel "a NUL byte: the rows read around it" "$(field "$TMP/out" 2 1)" 3 0
close_rel "a NUL byte: the largest difference (none)" "$(field "$TMP/out" 2 3)" 0 0
checks=$((checks + 1))
grep -qF "nul:3: a NUL byte at character 10: a line must be text" "$TMP/err" ||
    fail "a NUL byte: stderr $(cat "$TMP/err")"

# a 1 MB field is named by its first characters and its length, on one short line
awk 'BEGIN { s = "x"; while (length(s) < 1048576) s = s s
             print "r1 r2 volume gap force"; print "1e-3 1e-3 " s " 0 0" }' >"$TMP/wide"
"$CB" replay richefeu --columns r1=1,r2=2,volume=3,gap=4,force=5 "$TMP/wide" >"$TMP/out" 2>"$TMP/err"
close_rel "a 1 MB field: exit status" "$?" 1 0
checks=$((checks + 1))
grep -qF "wide:2: column 3 (volume) is 'xxxxxxxxxx" "$TMP/err" &&
    grep -qF "...' (1048576 bytes), not a decimal number" "$TMP/err" ||
    fail "a 1 MB field: stderr $(head -c 300 "$TMP/err")"
checks=$((checks + 1))
[ "$(wc -c <"$TMP/err")" -lt 500 ] || fail "a 1 MB field: $(wc -c <"$TMP/err") bytes on stderr"
# the same in ITEM: NUMBER OF ENTRIES
awk 'BEGIN { s = "7"; while (length(s) < 1048576) s = s s
             print "ITEM: NUMBER OF ENTRIES"; print "x" s; print "ITEM: ENTRIES a b c d e" }' >"$TMP/wide.dump"
"$CB" replay richefeu --columns r1=1,r2=2,volume=3,gap=4,force=5 "$TMP/wide.dump" >"$TMP/out" 2>"$TMP/err"
close_rel "a 1 MB count: exit status" "$?" 1 0
checks=$((checks + 1))
grep -qF "wide.dump:2: ITEM: NUMBER OF ENTRIES: 'x777777" "$TMP/err" &&
    grep -qF "...' (1048577 bytes) is not a count" "$TMP/err" ||
    fail "a 1 MB count: stderr $(head -c 300 "$TMP/err")"
checks=$((checks + 1))
[ "$(wc -c <"$TMP/err")" -lt 500 ] || fail "a 1 MB count: $(wc -c <"$TMP/err") bytes on stderr"

finish
