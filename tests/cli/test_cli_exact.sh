#!/bin/sh
# capbridge exact: the plumbing around the Laplace-Young solver (columns, the --curve gaps
# from 0 to the rupture distance inclusive, --gap and --rupture agreeing with --curve).
# The solver's accuracy is tested by the core's own tests.
. "$(dirname "$0")/lib.sh"

G="--r1 1e-3 --r2 5e-4 --volume 1e-11 --theta 10 --gamma 0.0206"
HEADER="gap,force,force_contact1,force_contact2,filling_angle1,filling_angle2,pressure,neck_radius,volume"

"$CB" exact $G --rupture >"$TMP/rupture" 2>"$TMP/err" || fail "--rupture: exit $? ($(cat "$TMP/err"))"
"$CB" exact $G --curve 5 >"$TMP/curve" 2>"$TMP/err" || fail "--curve 5: exit $? ($(cat "$TMP/err"))"
d=$(field "$TMP/rupture" 2 1)
for f in rupture curve; do
    checks=$((checks + 1))
    [ "$(sed -n 1p "$TMP/$f")" = "$HEADER" ] || fail "--$f: header $(sed -n 1p "$TMP/$f")"
done
checks=$((checks + 1))
awk -F, -v d="$d" 'NR == 1 { next }
    { n++
      if (NF != 9) { print "row " n ": " NF " columns"; bad = 1 }
      want = (n == 5) ? d : d * ((n - 1) / 4)
      diff = $1 - want; if (diff < 0) diff = -diff
      if (diff > 1e-15 * d) { printf "row %d: gap %.17g, expected %.17g\n", n, $1, want; bad = 1 }
      if (!($2 > 0)) { print "row " n ": force " $2; bad = 1 } }
    END { if (n != 5) { print n " rows"; bad = 1 }; exit bad }' "$TMP/curve" >"$TMP/why" ||
    fail "--curve 5: $(head -3 "$TMP/why")"
close_rel "--rupture gives a positive distance" "$(awk -v d="$d" 'BEGIN { print (d > 0) }')" 1 0

# --gap at a gap of the curve gives that row (to the solver's own tolerance)
g=$(field "$TMP/curve" 3 1)
"$CB" exact $G --gap "$g" >"$TMP/one" 2>"$TMP/err" || fail "--gap $g: exit $? ($(cat "$TMP/err"))"
close_rel "--gap: gap" "$(field "$TMP/one" 2 1)" "$g" 0
close_rel "--gap: force as in --curve" "$(field "$TMP/one" 2 2)" "$(field "$TMP/curve" 3 2)" 1e-6
close_rel "--curve: last row force as --rupture" "$(field "$TMP/curve" 6 2)" "$(field "$TMP/rupture" 2 2)" 1e-6

finish
