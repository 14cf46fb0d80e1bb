#!/bin/sh
# capbridge force / curve / rupture for the richefeu law against a hand computation of
# Richefeu 2007 eqs. 4-11 in awk (lib.sh), to 1e-12 relative.
. "$(dirname "$0")/lib.sh"

# One case per line: r1 r2 volume gap gamma theta c   (law keywords: gamma, theta, c)
cat >"$TMP/cases" <<'CASES'
1e-3 1e-3 1e-11 0 0.0728 0 0.9
1e-3 1e-3 1e-11 5e-5 0.0728 0 0.9
1e-3 5e-4 1e-11 2e-5 0.0728 10 0.9
5e-4 2e-3 3e-12 1e-5 0.0206 25 0.8
2.381e-3 2.381e-3 1.36e-11 1e-4 0.0206 0 0.9
1e-3 1e-3 1e-11 -1e-6 0.0728 0 0.9
1e-3 1e-3 1e-11 3e-4 0.0728 0 0.9
CASES

while read -r r1 r2 v gap gamma theta c; do
    label="force r1=$r1 r2=$r2 V=$v gap=$gap gamma=$gamma theta=$theta c=$c"
    if ! "$CB" force richefeu gamma "$gamma" theta "$theta" c "$c" \
        --r1 "$r1" --r2 "$r2" --volume "$v" --gap "$gap" >"$TMP/out" 2>"$TMP/err"; then
        fail "$label: exit status $? ($(cat "$TMP/err"))"
        continue
    fi
    checks=$((checks + 1))
    [ "$(sed -n 1p "$TMP/out")" = "gap,force,stiffness,rupture_distance" ] ||
        fail "$label: header '$(sed -n 1p "$TMP/out")'"
    expected=$(awk -v r1="$r1" -v r2="$r2" -v v="$v" -v gap="$gap" -v gamma="$gamma" \
        -v theta="$theta" -v c="$c" "$RICHEFEU_AWK"' BEGIN {
        f = rf_force(r1, r2, v, gap, gamma, theta, c)
        lambda = rf_lambda(r1, r2, v, c)
        k = (gap < 0 || f == 0) ? 0 : -f / lambda   # dF/dgap; 0 in overlap and beyond rupture
        printf "%.17g %.17g %.17g\n", f, k, rf_rupture(v, theta) }')
    set -- $expected
    close_rel "$label: gap" "$(field "$TMP/out" 2 1)" "$gap" 0
    close_rel "$label: force" "$(field "$TMP/out" 2 2)" "$1" 1e-12
    close_rel "$label: stiffness" "$(field "$TMP/out" 2 3)" "$2" 1e-12
    close_rel "$label: rupture distance" "$(field "$TMP/out" 2 4)" "$3" 1e-12
    "$CB" rupture richefeu theta "$theta" --r1 "$r1" --r2 "$r2" --volume "$v" >"$TMP/rupture" ||
        fail "$label: rupture exit status $?"
    close_rel "$label: rupture subcommand" "$(field "$TMP/rupture" 2 1)" "$3" 1e-12
done <"$TMP/cases"

# overlap none: no capillary force in overlap (Gladkyy eq. 4), the law's value at gap 0
"$CB" force richefeu overlap none --r1 1e-3 --r2 1e-3 --volume 1e-11 --gap -1e-9 >"$TMP/out"
close_rel "overlap none, gap < 0" "$(field "$TMP/out" 2 2)" 0 0
"$CB" force richefeu overlap none --r1 1e-3 --r2 1e-3 --volume 1e-11 --gap 0 >"$TMP/out"
close_rel "overlap none, gap 0" "$(field "$TMP/out" 2 2)" \
    "$(awk "$RICHEFEU_AWK"' BEGIN { printf "%.17g", rf_force(1e-3, 1e-3, 1e-11, 0, 0.0728, 0, 0.9) }')" 1e-12

# curve: default 21 points from 0 to 1.05 x rupture distance, then an explicit range
compare_curve() { # LABEL FILE R1 R2 V THETA FROM TO POINTS
    label=$1
    checks=$((checks + 1))
    awk -F, "$RICHEFEU_AWK"'
        NR == 1 { if ($0 != "gap,force,stiffness") { print "header " $0; bad = 1 }; next }
        {
            n++
            g = (n == points) ? to : from + (to - from) * ((n - 1) / (points - 1))
            f = rf_force(r1, r2, v, g, 0.0728, theta, 0.9)
            k = (g < 0 || f == 0) ? 0 : -f / rf_lambda(r1, r2, v, 0.9)
            if (!rf_close($1, g, 1e-15, 1e-300)) { print "row " n ": gap " $1 ", expected " g; bad = 1 }
            if (!rf_close($2, f, 1e-12, 1e-300)) { print "row " n ": force " $2 ", expected " f; bad = 1 }
            if (!rf_close($3, k, 1e-12, 1e-300)) { print "row " n ": stiffness " $3 ", expected " k; bad = 1 }
        }
        END {
            if (n != points) { print n " rows, expected " points; bad = 1 }
            exit bad }' \
        r1="$3" r2="$4" v="$5" theta="$6" from="$7" to="$8" points="$9" "$2" >"$TMP/why" ||
        fail "$label: $(head -3 "$TMP/why")"
}

"$CB" curve richefeu --r1 1e-3 --r2 5e-4 --volume 1e-11 >"$TMP/curve" || fail "curve exit $?"
to=$(awk "$RICHEFEU_AWK"' BEGIN { printf "%.17g", 1.05 * rf_rupture(1e-11, 0) }')
compare_curve "curve, defaults" "$TMP/curve" 1e-3 5e-4 1e-11 0 0 "$to" 21
close_rel "curve, last gap is 1.05 x rupture" "$(field "$TMP/curve" 22 1)" "$to" 1e-12
close_rel "curve, force beyond rupture" "$(field "$TMP/curve" 22 2)" 0 0

"$CB" curve richefeu theta 20 --r1 2e-3 --r2 1e-3 --volume 2e-11 --points 7 --from -1e-5 \
    --to 2e-4 >"$TMP/curve" || fail "curve (range) exit $?"
compare_curve "curve, --from -1e-5 --to 2e-4 --points 7" "$TMP/curve" 2e-3 1e-3 2e-11 20 -1e-5 2e-4 7

# --plane (a wall): a closed-form law is its Derjaguin-equivalent pair, two spheres 2 r1, to
# the digit; the table law's rupture distance at a plane within 2e-4 of the exact one
for gap in 0 2e-5 1e-4; do
    "$CB" force richefeu theta 20 --r1 1e-3 --plane --volume 1e-11 --gap $gap >"$TMP/plane" &&
        "$CB" force richefeu theta 20 --r1 2e-3 --r2 2e-3 --volume 1e-11 --gap $gap >"$TMP/pair" ||
        fail "force --plane at gap $gap: exit $?"
    checks=$((checks + 1))
    cmp -s "$TMP/plane" "$TMP/pair" || fail "force --plane at gap $gap: $(sed -n 2p "$TMP/plane") against the pair's $(sed -n 2p "$TMP/pair")"
done
"$CB" rupture table theta 20 --r1 1e-3 --plane --volume 1e-11 >"$TMP/table" &&
    "$CB" exact --theta 20 --r1 1e-3 --plane --volume 1e-11 --rupture >"$TMP/exact" ||
    fail "rupture table --plane: exit $?"
close_rel "rupture table --plane against exact --plane" "$(sed -n 2p "$TMP/table")" \
    "$(sed -n 2p "$TMP/exact" | cut -d, -f1)" 2e-4

finish
