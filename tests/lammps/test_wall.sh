#!/bin/sh
# Bridges between grains and flat walls (fix capillary/wall; the core's sphere-plane pair,
# r2 = CB_PLANE).  in.wall: one sphere driven away from a zplane wall (above a floor, side
# 1, and below a ceiling, side -1) from an overlap where the bridge forms to past its
# rupture.  At every step the force on the sphere equals the core's (`capbridge force
# --plane` at that gap): along the normal n (from the wall to the sphere) -F_cap -
# c_n v.n, across it -c_t v_t, the torque -r n x f_t, to 1e-9 relative; the fix's vector
# gives the bridge, its volume and the opposite force on the wall; the bridge breaks at
# the core's rupture distance.  The table law's force follows the exact Laplace-Young
# sphere-plane bridge (`capbridge exact --plane`) to 2e-3.  Keyword angle: the law at the
# mean-cosine angle of grain and wall (cb_wall_contact_angle).
# zcylinder: the same bridge with the cylinder's tangent plane at the grain, off the axes.
# Region walls (fix capillary/wall region): a block region's face as the floor and the
# ceiling, a cylinder region as the zcylinder, each checked as those; the block moving
# along x with the sphere (region move): no tangential viscous force, the normal one kept.
# Under Protocols 2 and 3 the sphere's free liquid forms the bridge and returns to it at
# rupture; 192 grains settling on a wet floor (in.wall_liquid, fix wall/gran's or fix
# wall/gran/region's contact: the floor a plane or a region's face)
# under Protocols 1 (the floor's pairs among the candidates), 2 and 3 conserve the liquid
# at every output on 1, 2 and 3 ranks and across a restart file (the wall bridges and
# their liquid come back).
. "$(dirname "$0")/lib.sh" "$@"

R=5e-4 V=2e-11 VX=0.02 VZ=1 DT=2e-6 N=200 RC=5e-3

run() {  # run LOG NP SIDE LAW "KEYS" ["ANGLE_KEYS" [PROTOCOL]]
    lmp "$2" "$1" -in "$DECKS/in.wall" -var r $R -var volume $V -var law "$4" -var keys "$5" \
        -var angle_keys "${6:-}" -var protocol "${7:-none}" -var side "$3" -var vx $VX \
        -var vz $VZ -var dt $DT -var nsteps $N -var wall "${WALL:-zplane}" -var rc $RC \
        -var wallvx "${WALLVX:-0}" -var jump "${JUMP:-0}" \
        >/dev/null 2>&1 ||
        { fail "$(basename "$1"): LAMMPS failed: $(grep -h -m1 ERROR "$1" "$1.screen")"; return 1; }
}

# expected LOG SIDE LAW "KEYS": per thermo row, the row and the core's "gap,force,..." row
expected() {
    thermo "$1" | while read -r step z fx fz ty wy bridges volume wfx wfz free; do
        gap=$(awk -v z="$z" -v s="$2" -v r=$R 'BEGIN { printf "%.17g", s * z - r }')
        # shellcheck disable=SC2086
        row=$("$CB" force "$3" $4 --r1 $R --plane --volume $V --gap "$gap" | tail -1)
        echo "$step $z $fx $fz $ty $wy $bridges $volume $wfx $wfz $free $row"
    done
}

# compare LABEL SIDE [PROTOCOL [WALLVX]]: the rows of expected against the force, torque
# and wall force (the wall moving along x at WALLVX); under a protocol the sphere's free
# liquid is 0 while the bridge holds V, V after
compare() {
    awk -v label="$1" -v s="$2" -v protocol="${3:-none}" -v wvx="${4:-0}" -v vx=$VX -v vz=$VZ -v r=$R -v vol=$V '
    function abs(x) { return x < 0 ? -x : x }
    function same(name, got, want, scale) {
        if (abs(got - want) <= 1e-9 * scale) return
        if (bad < 5) printf "%s step %d: %s LAMMPS %.17g, core %.17g\n", label, $1, name, got, want
        bad++
    }
    {
        split($12, c, ",")   # gap, force, stiffness, rupture[, c_n, c_t]
        if (protocol != "none") same("free liquid", $11, $7 == 1 ? 0 : vol, vol)
        rate = $1 > 0 ? vz : 0                    # fix move sets the velocity from step 1 on
        tangential = $1 > 0 ? vx - wvx : 0
        if ($7 == 1) {
            if (c[1] > c[4]) { printf "%s step %d: a bridge at gap %.6g beyond the rupture distance %.6g\n", label, $1, c[1], c[4]; bad++ }
            viscous = c[1] > 0 ? c[5] * rate : 0  # a stretched bridge only
            ftx = c[1] > 0 ? -c[6] * tangential : 0
            fn = -c[2] - viscous                  # along n, away from the wall
            scale = c[2] + abs(viscous) + abs(ftx)
            same("fz", $4, s * fn, scale); same("fx", $3, ftx, scale)
            same("torque y", $5, -r * s * ftx, r * scale)
            same("wall fz", $10, -s * fn, scale); same("wall fx", $9, -ftx, scale)
            same("bridge volume", $8, vol, vol)
            held++; last = c[1]
        } else {
            if (held == 0) { printf "%s step %d: no bridge at the start\n", label, $1; bad++ }
            if (!broken && c[1] < c[4]) { printf "%s step %d: broken at gap %.6g before the rupture distance %.6g\n", label, $1, c[1], c[4]; bad++ }
            if ($3 != 0 || $4 != 0) { printf "%s step %d: a force without a bridge\n", label, $1; bad++ }
            broken++; rupture = c[4]
        }
        if ($6 != 0) { printf "%s step %d: omega %g, expected 0 (fix move)\n", label, $1, $6; bad++ }
    }
    END {
        if (held < 50 || broken < 10) { printf "%s: %d steps with a bridge, %d after it broke\n", label, held, broken; bad++ }
        printf "%s: %d steps with a bridge, force and torque as the core'"'"'s to 1e-9, broken between gaps %.6g and %.6g m (rupture distance %.6g)\n", label, held, last, last + vz * 2e-6, rupture
        exit bad > 0 }' >"$TMP/why" || { fail "$(head -5 "$TMP/why")"; return; }
    cat "$TMP/why"
}

keys="gamma 0.0728 viscosity 0.5 min_gap 2e-7"
for wall in zplane rplane; do
    for side in 1 -1; do
        log="$TMP/wall-$wall-side$side.log"
        WALL=$wall run "$log" 1 $side richefeu "$keys" || continue
        checks=$((checks + 1))
        expected "$log" $side richefeu "$keys" >"$TMP/rows"
        compare "richefeu viscous, $wall, side $side" $side <"$TMP/rows"
    done
done
# the region moving with the sphere along x: the contact point at rest on the wall
log="$TMP/wall-rplane-moving.log"
if WALL=rplane WALLVX=$VX run "$log" 1 1 richefeu "$keys"; then
    checks=$((checks + 1))
    expected "$log" 1 richefeu "$keys" >"$TMP/rows"
    compare "richefeu viscous, rplane moving at $VX m/s along x" 1 none $VX <"$TMP/rows"
fi

# the time step, 2e-6 s, is above the wall bridge's viscous limit (c = 4 times a pair's of
# equal spheres): warned by the fix in the viscous run only
checks=$((checks + 1))
grep -q "fix capillary/wall: time step 2e-06 s exceeds the limit .* of the wall bridges' viscous force for type 1" "$TMP/wall-zplane-side1.log" ||
    fail "no warning of the wall bridges' viscous time-step limit: $(grep -h WARNING "$TMP/wall-zplane-side1.log")"

# Protocols 2 and 3: the sphere's free liquid V forms the bridge at contact, and all of it
# returns to the sphere at rupture (the wall holds none)
for protocol in protocol2 protocol3; do
    log="$TMP/wall-$protocol.log"
    run "$log" 1 1 richefeu "gamma 0.0728" "" $protocol || continue
    checks=$((checks + 1))
    expected "$log" 1 richefeu "gamma 0.0728" >"$TMP/rows"
    compare "richefeu, $protocol" 1 $protocol <"$TMP/rows"
    checks=$((checks + 1))
    ! grep -q "WARNING: fix capillary/wall: time step" "$log" ||
        fail "$protocol: a wall time-step warning without viscosity: $(grep -h -m1 WARNING "$log")"
done

# the region jumping 1 mm away at step 20 (the face beyond the sphere's reach): the bridge
# breaks at that step, under Protocol 2 all its liquid back to the sphere, no force after
log="$TMP/wall-rplane-jump.log"
if WALL=rplane JUMP=20 run "$log" 1 1 richefeu "gamma 0.0728" "" protocol2; then
    checks=$((checks + 1))
    thermo "$log" | awk -v vol=$V '
    function abs(x) { return x < 0 ? -x : x }
    $1 < 20 && !($7 == 1 && abs($11) <= 1e-9 * vol && $4 < 0) { bad++ }
    $1 >= 20 && !($7 == 0 && abs($11 - vol) <= 1e-9 * vol && $4 == 0 && $10 == 0) { bad++ }
    { rows++ }
    END {
        printf "rplane jumping away at step 20 (protocol2): %d rows, %d not as expected (a bridge to step 19, none from 20 on, its liquid back on the sphere)\n", rows, bad
        exit !(rows == 201 && bad == 0) }' >"$TMP/why" || fail "$(cat "$TMP/why")"
    cat "$TMP/why"
fi

# zcylinder: the inside of a cylinder of radius RC about z, the sphere at 45 degrees
# between x and y driven to the axis: the bridge of the cylinder's tangent plane, its force
# along the wall's normal at the grain (half of it squared on x and on y), the opposite
# force on the wall, broken at the core's rupture distance
# (rcylinder: the same cylinder as a region)
for wall in zcylinder rcylinder; do
    log="$TMP/wall-$wall.log"
    WALL=$wall run "$log" 1 1 willett "gamma 0.0728" || continue
    checks=$((checks + 1))
    thermo "$log" | while read -r step rho fx fy ty wy bridges volume wfx wfz free; do
        gap=$(awk -v rho="$rho" -v rc=$RC -v r=$R 'BEGIN { printf "%.17g", rc - rho - r }')
        echo "$step $fx $fy $bridges $wfx $("$CB" force willett gamma 0.0728 --r1 $R --plane --volume $V --gap "$gap" | tail -1)"
    done >"$TMP/rows"
    awk -v wall=$wall '
    function abs(x) { return x < 0 ? -x : x }
    function same(name, got, want, scale) {
        if (abs(got - want) <= 1e-9 * scale) return
        if (bad < 5) printf "%s step %d: %s LAMMPS %.17g, core %.17g\n", wall, $1, name, got, want
        bad++
    }
    {
        split($6, c, ",")
        if ($4 == 1) {
            component = c[2] / sqrt(2)   # the attraction, towards the wall: +x and +y
            same("fx", $2, component, c[2]); same("fy", $3, component, c[2])
            same("wall fx", $5, -component, c[2])
            if (c[1] > c[4]) { printf "%s step %d: a bridge beyond the rupture distance\n", wall, $1; bad++ }
            held++; last = c[1]
        } else {
            if (held == 0) { printf "%s step %d: no bridge at the start\n", wall, $1; bad++ }
            if (!broken && c[1] < c[4]) { printf "%s step %d: broken at gap %.6g before the rupture distance %.6g\n", wall, $1, c[1], c[4]; bad++ }
            if ($2 != 0 || $3 != 0) { printf "%s step %d: a force without a bridge\n", wall, $1; bad++ }
            broken++; rupture = c[4]
        }
    }
    END {
        if (held < 50 || broken < 10) { printf "%s: %d steps with a bridge, %d after it broke\n", wall, held, broken; bad++ }
        printf "willett, %s: %d steps with a bridge, force on x and y as the core'"'"'s to 1e-9, broken after gap %.6g m (rupture distance %.6g)\n", wall, held, last, rupture
        exit bad > 0 }' "$TMP/rows" >"$TMP/why" || fail "$(head -5 "$TMP/why")"
    cat "$TMP/why"
done

# keyword angle: grain 20 degrees, wall 50: the law at acos((cos 20 + cos 50) / 2)
mean=$(awk 'BEGIN { d = atan2(0, -1) / 180; c = (cos(20 * d) + cos(50 * d)) / 2
                    printf "%.17g", atan2(sqrt(1 - c * c), c) / d }')
log="$TMP/wall-angle.log"
if run "$log" 1 1 willett "gamma 0.0728 theta 20" "angle 50"; then
    checks=$((checks + 1))
    expected "$log" 1 willett "gamma 0.0728 theta $mean" >"$TMP/rows"
    compare "willett, grain 20 and wall 50 degrees (theta $mean)" 1 <"$TMP/rows"
fi

# the table law against the exact sphere-plane bridge, every 10th step in contact
log="$TMP/wall-table.log"
if run "$log" 1 1 table "gamma 0.0728"; then
    checks=$((checks + 1))
    thermo "$log" | awk 'NR % 10 == 1 && $7 == 1' | while read -r step z fx fz rest; do
        gap=$(awk -v z="$z" -v r=$R 'BEGIN { g = z - r; printf "%.17g", g < 0 ? 0 : g }')
        exact=$("$CB" exact --r1 $R --plane --volume $V --gap "$gap" | tail -1 | cut -d, -f2)
        echo "$step $gap $fz $exact"
    done | awk '
    function abs(x) { return x < 0 ? -x : x }
    { n++; e = abs(-$3 - $4) / $4; if (e > worst) { worst = e; at = $2 } }
    END {
        printf "table law at a wall: %d gaps, largest error against the exact bridge %.3g (gap %.3g m)\n", n, worst, at
        exit !(n >= 8 && worst < 2e-3) }' >"$TMP/why" || fail "$(cat "$TMP/why")"
    cat "$TMP/why"
fi
# grains on a wet floor: the liquid conserved, the floor wetted, the bridges restarted
scene_data "$TMP/floor.data" 8 8 3 7 0.1
sed 's/^0 .* zlo zhi$/0 1e-2 zlo zhi/' "$TMP/floor.data" >"$TMP/floor-high.data"
floor() {  # floor LOG NP MODE RESTART WALL
    lmp "$2" "$1" -in "$DECKS/in.wall_liquid" -var data "$TMP/floor-high.data" -var mode "$3" \
        -var nsteps 3000 -var restart "$4" -var out "$1" -var wall "$5" >/dev/null 2>&1 ||
        { fail "$(basename "$1"): LAMMPS failed: $(grep -h -m1 ERROR "$1" "$1.screen")"; return 1; }
}
# the floor as a plane (fix wall/gran zplane) and as a region's face (fix wall/gran/region)
for wall in plane region; do
    for mode in protocol1 protocol2 protocol3; do
        for np in 1 2 3; do
            log="$TMP/floor-$wall-$mode-np$np.log"
            floor "$log" $np $mode no $wall || continue
            checks=$((checks + 1))
            thermo "$log" | awk -v label="floor ($wall) $mode np $np" '
            function abs(x) { return x < 0 ? -x : x }
            { rows++; if (abs($5) > worst) worst = abs($5); walls = $6; held = $7 }
            END {
                printf "%s: %d outputs, total liquid within %.2g of its start, %d floor bridges holding %.3g m^3 at the end\n", label, rows, worst, walls, held
                exit !(rows == 31 && worst < 1e-12 && walls >= 5 && held > 0) }' >"$TMP/why" ||
                { fail "$(cat "$TMP/why")"; continue; }
            cat "$TMP/why"
        done
        # a restart file written at step 1500 on 2 ranks, read in a new LAMMPS: the floor
        # bridges and the total come back as they were, and the liquid stays conserved
        log="$TMP/floor-$wall-$mode-restart.log"
        floor "$log" 2 $mode yes $wall || continue
        checks=$((checks + 1))
        thermo "$log" | awk -v label="floor ($wall) $mode restart" '
        function abs(x) { return x < 0 ? -x : x }
        { rows++; if (abs($5) > worst) worst = abs($5) }
        $1 == 1500 && !seen { seen = 1; walls = $6; held = $7; total = $4; next }
        $1 == 1500 { back = ($6 == walls && abs($7 - held) <= 1e-12 * held && abs($4 - total) <= 1e-12 * total) }
        END {
            printf "%s: %d floor bridges holding %.6g m^3 at step 1500, after the restart %s; total liquid within %.2g of its start\n", label, walls, held, back ? "the same" : "NOT the same", worst
            exit !(rows == 33 && back && walls >= 5 && worst < 1e-12) }' >"$TMP/why" ||
            { fail "$(cat "$TMP/why")"; continue; }
        cat "$TMP/why"
    done
done

# the restart file of one wall read by a fix with two: an error naming both counts
checks=$((checks + 1))
log="$TMP/floor-reread.log"
if lmp 1 "$log" -in "$DECKS/in.wall_liquid" -var mode protocol2 -var reread yes \
    -var out "$TMP/floor-plane-protocol2-restart.log" >/dev/null 2>&1; then
    fail "a restart file of one wall read with two walls: no error"
else
    line=$(grep -h -m1 ERROR "$log" "$log.screen" | head -1)
    echo "$line" | grep -q "the restart file holds 7 values per atom for this fix, the input's 2 wall(s) need 14" ||
        fail "restart with another wall count: '$line'"
    echo "reread: $line"
fi
finish
