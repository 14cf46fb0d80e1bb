#!/bin/sh
# capbridge pulloff: the static law along the pulled curve, the rupture step, the exact
# velocity Verlet step order (an independent awk integrator), second-order convergence,
# contact with damping, and the failure when the bridge never breaks.
. "$(dirname "$0")/lib.sh"

G="--r1 1e-3 --r2 1e-3 --volume 1e-11"
HEADER="step,time,x1,v1,x2,gap,capillary_force,contact_force,bridge"

# --- A. sphere 1 nearly immovable (density 1e12): the capillary column is the static law
"$CB" pulloff richefeu $G --density 1e12 >"$TMP/heavy" 2>"$TMP/err" || fail "heavy: exit $? ($(cat "$TMP/err"))"
"$CB" rupture richefeu $G >"$TMP/rupture"
d=$(field "$TMP/rupture" 2 1)
close_rel "heavy: header rupture distance" \
    "$(awk '/^# rupture_distance = / { print $4 }' "$TMP/heavy")" "$d" 0
checks=$((checks + 1))
[ "$(grep -v '^#' "$TMP/heavy" | head -1)" = "$HEADER" ] || fail "heavy: CSV header"
# default dt = min(0.02 pi sqrt(m/k_n), d / (2000 v)), m the reduced mass
dt_expected=$(awk -v d="$d" 'BEGIN { pi = atan2(0, -1); m1 = 4 * pi / 3 * 1e-9 * 1e12
    m = m1 * m1 / (m1 + m1); a = 0.02 * pi * sqrt(m / 1e3); b = d / (1e-4 * 2000)
    printf "%.17g", a < b ? a : b }')
close_rel "heavy: default dt" "$(awk '/^# dt = / { print $4 }' "$TMP/heavy")" "$dt_expected" 1e-12

checks=$((checks + 1))
awk -F, -v d="$d" "$RICHEFEU_AWK"'
    /^#/ || $1 == "step" { next }
    {
        rows++
        if ($9 == 1) {
            if (broken) { print "step " $1 ": bridge back after the rupture"; bad = 1 }
            if ($6 > d) { print "step " $1 ": bridge at gap " $6 " > rupture distance " d; bad = 1 }
            f = rf_force(1e-3, 1e-3, 1e-11, $6, 0.0728, 0, 0.9)
            if (!rf_close($7, f, 1e-9, 0)) { print "step " $1 ": capillary " $7 ", static law " f; bad = 1 }
            last_gap = $6
        } else {
            if (!broken) {
                broken = $1
                if (!($6 > d)) { print "step " $1 ": bridge 0 at gap " $6 " <= " d; bad = 1 }
                if (!(last_gap <= d)) { print "step " $1 ": the gap before exceeded " d; bad = 1 }
            }
            if ($7 != 0) { print "step " $1 ": capillary force " $7 " without a bridge"; bad = 1 }
        }
        if ($8 != 0) { print "step " $1 ": contact force " $8 " with gap " $6; bad = 1 }
        last = $1
    }
    END {
        if (!broken) { print "the bridge never broke"; bad = 1 }
        if (last - broken != 10) { print "ran " last - broken " steps after the rupture, not 10"; bad = 1 }
        if (rows != last + 1) { print rows " rows for steps 0.." last; bad = 1 }
        exit bad }' "$TMP/heavy" >"$TMP/why" || fail "heavy: $(head -5 "$TMP/why")"

# --- B. the step order, replayed by an independent integrator in awk (and C.-D. use it)
# replica FILE DENSITY VELOCITY KN ALPHA DT: compares every printed row to 1e-9
replica() {
    checks=$((checks + 1))
    awk -F, -v rho="$2" -v vel="$3" -v kn="$4" -v alpha="$5" -v dt="$6" "$RICHEFEU_AWK"'
    function forces() {
        gap = (x2 - x1) - radsum
        if (active && gap > d) active = 0
        else if (!active && gap <= 0) active = 1
        cap = active ? rf_force(r1, r2, vol, gap, 0.0728, 0, 0.9) : 0
        con = 0
        if (gap < 0) {
            con = kn * (-gap)
            rate = vel - v1
            if (rate < 0) con += eta * (-rate)
        }
        f1 = cap - con
    }
    function same(name, got, want, floor_) {
        if (!rf_close(got, want, 1e-9, floor_)) {
            printf "step %d: %s %.17g, replica %.17g\n", $1, name, got, want; bad = 1
        }
    }
    BEGIN {
        r1 = 1e-3; r2 = 1e-3; vol = 1e-11; pi = rf_pi()
        m1 = 4.0 * pi / 3.0 * r1 * r1 * r1 * rho; m2 = 4.0 * pi / 3.0 * r2 * r2 * r2 * rho
        m = m1 * m2 / (m1 + m2); eta = 2 * alpha * sqrt(m * kn)
        d = rf_rupture(vol, 0); radsum = r1 + r2; dtfm = 0.5 * dt / m1
        x1 = 0; v1 = 0; x2 = radsum; active = 0; n = 0
        forces()                                  # step 0: the bridge forms at contact
    }
    /^#/ || $1 == "step" { next }
    {
        while (n < $1) {
            n++
            v1 += dtfm * f1                       # 1. half kick
            x1 += dt * v1                         # 2. drift
            x2 = radsum + vel * (n * dt)          # 3. driven sphere
            forces()                              # 4.-6.
            v1 += dtfm * f1                       # 7. half kick
        }
        rows++
        same("time", $2, n * dt, 1e-300)
        same("x1", $3, x1, 1e-15); same("v1", $4, v1, 1e-12); same("x2", $5, x2, 1e-300)
        same("gap", $6, gap, 1e-15); same("capillary_force", $7, cap, 1e-15)
        same("contact_force", $8, con, 1e-12)
        if ($9 != active) { print "step " $1 ": bridge " $9 ", replica " active; bad = 1 }
        if (bad) exit 1
    }
    END { if (rows < 2) { print "only " rows " rows"; bad = 1 }; exit bad }' "$1" >"$TMP/why" ||
        fail "replica of $1: $(head -3 "$TMP/why")"
}

for dt in 2e-6 1e-6 5e-7; do
    "$CB" pulloff richefeu $G --velocity 0.5 --dt "$dt" >"$TMP/light_$dt" 2>"$TMP/err" ||
        fail "light, dt $dt: exit $? ($(cat "$TMP/err"))"
done
replica "$TMP/light_1e-6" 2500 0.5 1e3 0 1e-6

# --- C. second order: halving dt divides the change of x1 at a fixed time by about 4
x_at() { awk -F, -v s="$2" '/^#/ { next } $1 == s { print $3 }' "$1"; }
close_rel "time of step 100 at dt 2e-6" "$(awk -F, '$1 == 100 { print $2 }' "$TMP/light_2e-6")" 2e-4 1e-12
xa=$(x_at "$TMP/light_2e-6" 100)
xb=$(x_at "$TMP/light_1e-6" 200)
xc=$(x_at "$TMP/light_5e-7" 400)
checks=$((checks + 1))
awk -v a="$xa" -v b="$xb" -v c="$xc" 'BEGIN {
    if (!(b > 1e-8)) { print "sphere 1 did not move: x1 = " b; exit 1 }
    r = (a - b) / (b - c)
    printf "x1(2e-4 s) = %.17g, %.17g, %.17g; ratio of changes %.4f\n", a, b, c, r
    exit !(r > 3.6 && r < 4.4) }' >"$TMP/why" || fail "second order: $(cat "$TMP/why")"
echo "second order: $(cat "$TMP/why")"

# --- D. contact and damping: a slow pull, sphere 1 caught in the well, never breaks
for alpha in 0 0.3; do
    "$CB" pulloff richefeu $G --damping "$alpha" --max-steps 3000 >"$TMP/stuck_$alpha" 2>"$TMP/err"
    code=$?
    checks=$((checks + 1))
    [ "$code" -eq 1 ] || fail "stuck, damping $alpha: exit $code, expected 1"
    checks=$((checks + 1))
    grep -q "did not rupture within --max-steps 3000" "$TMP/err" ||
        fail "stuck, damping $alpha: message '$(cat "$TMP/err")'"
    dt=$(awk '/^# dt = / { print $4 }' "$TMP/stuck_$alpha")
    replica "$TMP/stuck_$alpha" 2500 1e-4 1e3 "$alpha" "$dt"
    checks=$((checks + 1))
    contacts=$(awk -F, '!/^#/ && $8 > 0' "$TMP/stuck_$alpha" | wc -l)
    [ "$contacts" -gt 100 ] || fail "stuck, damping $alpha: only $contacts rows in contact"
done

# --- E. --every keeps step 0, the rupture and the last step
"$CB" pulloff richefeu $G --velocity 0.5 --dt 1e-6 --every 100 >"$TMP/every"
checks=$((checks + 1))
awk -F, '/^#/ || $1 == "step" { next } { printf "%s%s", sep, $1; sep = " " } END { print "" }' \
    "$TMP/every" >"$TMP/steps"
last=$(awk -F, '!/^#/ { s = $1 } END { print s }' "$TMP/light_1e-6")
broke=$(awk -F, '!/^#/ && $9 == "0" { print $1; exit }' "$TMP/light_1e-6")
expected=$(awk -v l="$last" -v b="$broke" 'BEGIN { for (s = 0; s <= l; s++)
    if (s % 100 == 0 || s == b || s == l) { printf "%s%d", sep, s; sep = " " }; print "" }')
[ "$(cat "$TMP/steps")" = "$expected" ] || fail "--every 100: steps $(cat "$TMP/steps"), expected $expected"
checks=$((checks + 1))
[ "$(awk -F, -v b="$broke" '$1 == b' "$TMP/every")" = "$(awk -F, -v b="$broke" '$1 == b' "$TMP/light_1e-6")" ] ||
    fail "--every 100: the rupture row differs from the full run"

finish
