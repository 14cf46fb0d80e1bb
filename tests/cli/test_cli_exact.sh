#!/bin/sh
# capbridge exact: the plumbing around the Laplace-Young solver (columns, the --curve gaps
# from 0 to the rupture distance inclusive, --gap and --rupture agreeing with --curve,
# --plane and --theta2 reaching the solver).
# The solver's accuracy is tested by the core's own tests.
. "$(dirname "$0")/lib.sh"

G="--r1 1e-3 --r2 5e-4 --volume 1e-11 --theta 10 --gamma 0.0206"
HEADER="gap,force,force_contact1,force_contact2,filling_angle1,filling_angle2,pressure,neck_radius,volume,contact_radius1,contact_radius2"

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
      if (NF != 11) { print "row " n ": " NF " columns"; bad = 1 }
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

# --theta2 defaults to --theta: giving it equal changes nothing
"$CB" exact $G --theta2 10 --rupture >"$TMP/rupture2" 2>"$TMP/err" || fail "--theta2 10: exit $? ($(cat "$TMP/err"))"
close_rel "--theta2 = --theta: rupture as without it" "$(field "$TMP/rupture2" 2 1)" "$d" 0
# contact_radius1 = r1 sin(filling_angle1) on the sphere
close_rel "contact_radius1" "$(field "$TMP/rupture" 2 10)" \
    "$(awk -v a="$(field "$TMP/rupture" 2 5)" 'BEGIN { printf "%.17g", 1e-3 * sin(a) }')" 1e-12

# --plane: the bridge to a plane is the limit of a sphere 2 far larger than sphere 1; on
# the plane the filling angle is 0 and the contact line's radius is reported
P="--r1 1e-3 --volume 1e-11 --theta 10 --theta2 30 --gamma 0.0206"
"$CB" exact $P --plane --rupture >"$TMP/plane" 2>"$TMP/err" || fail "--plane: exit $? ($(cat "$TMP/err"))"
"$CB" exact $P --r2 1e3 --rupture >"$TMP/huge" 2>"$TMP/err" || fail "--r2 1e3: exit $? ($(cat "$TMP/err"))"
checks=$((checks + 1))
[ "$(sed -n 1p "$TMP/plane")" = "$HEADER" ] || fail "--plane: header $(sed -n 1p "$TMP/plane")"
close_rel "--plane: filling_angle2" "$(field "$TMP/plane" 2 6)" 0 0
close_rel "--plane: rupture as r2 = 1e6 r1" "$(field "$TMP/plane" 2 1)" "$(field "$TMP/huge" 2 1)" 1e-5
close_rel "--plane: force at rupture as r2 = 1e6 r1" "$(field "$TMP/plane" 2 2)" "$(field "$TMP/huge" 2 2)" 1e-5
close_rel "--plane: contact_radius2 as r2 = 1e6 r1" "$(field "$TMP/plane" 2 11)" "$(field "$TMP/huge" 2 11)" 1e-5

finish
