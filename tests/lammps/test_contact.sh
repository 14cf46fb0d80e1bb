#!/bin/sh
# Contact details of pair gran/capillary with two spheres:
#  - friction: a sliding contact carries the Coulomb limit mu f_contact (Richefeu 2007
#    eq. 12 with eq. 1's f_n); before it slides, k_t times the accumulated displacement;
#    a pair held by its bridge alone slides under mu F_cap;
#  - the normal dashpot: the restitution of a head-on collision, 'dashpot approach' and
#    'dashpot both', against the analytic values, and again from a restart file;
#  - the bridge's stored constants follow the coefficients (pair_coeff between two runs)
#    and the radii (a sphere growing under fix adapt): its force against the CLI's;
#  - the pair history of a dry first run widens for a wet one, the tangential spring kept
#    (1 and 2 ranks, and through a restart file);
#  - a bridge keeps its own rupture distance when the volume is lowered between runs (the
#    reach covers the bridges that exist); one that reaches the cutoff (a growing sphere)
#    ruptures there, with a warning;
#  - the neighbor reach: LAMMPS's neighbor cutoff is r1 + r2 + the core's reach (the rupture
#    distance of the bridge volume in use, fixed: the pair_coeff volume; a protocol: vmax,
#    plus 5 %) + skin.
. "$(dirname "$0")/lib.sh" "$@"

# richefeu, R = 1 mm, gamma 0.0728, theta 0: f_capillary at contact = 2 pi gamma R
FCAP=$(awk 'BEGIN { printf "%.17g", 2 * atan2(0, -1) * 0.0728 * 1e-3 }')
log="$TMP/friction.log"
if lmp 1 "$log" -in "$DECKS/in.contact" -var overlap 1e-6 -var vy 0.01 -var nsteps 1000 \
    -var vkw "volume 1e-11" >/dev/null 2>&1; then
    thermo "$log" >"$TMP/rows"
    # step 100: sticking, f_t = k_t |v| t = 100 * 0.01 * 100e-6; step 1000: sliding at
    # mu f_contact (Richefeu 2007 eq. 12 with eq. 1's f_n), the capillary force not added
    close_rel "friction: capillary force" "$(awk '$1 == 1000 { print $2 }' "$TMP/rows")" "$FCAP" 1e-12
    close_rel "friction: contact force k_n overlap" "$(awk '$1 == 1000 { print $3 }' "$TMP/rows")" 1e-3 1e-6
    close_rel "friction: sticking at step 100" "$(awk '$1 == 100 { print $4 }' "$TMP/rows")" 1e-4 1e-6
    close_rel "friction: sliding at mu f_contact" "$(awk '$1 == 1000 { print $4 }' "$TMP/rows")" 5e-4 1e-12
    echo "friction: tangential force at step 1000 $(awk '$1 == 1000 { print $4 }' "$TMP/rows") N, mu f_contact 5e-4 N"
else
    fail "friction: LAMMPS failed: $(grep -h -m1 ERROR "$log"*)"
fi

# a pair held in contact by its bridge alone (no other load; sphere 1 frozen, sphere 2
# translating only) settles where f_contact = F_cap, then slides under a tangential load
# of mu F_cap: the reading of eq. 12 that counts the attraction once (twice: 2 mu F_cap)
log="$TMP/held.log"
if lmp 1 "$log" -in "$DECKS/in.held" >/dev/null 2>&1; then
    load=$(sed -n 's/^SLIDING_LOAD //p' "$log" | head -1)
    mu_fcap=$(awk -v f="$FCAP" 'BEGIN { printf "%.17g", 0.4 * f }')
    close_rel "held by its bridge alone: the load it slides at, mu F_cap" "$load" "$mu_fcap" 0.03
    echo "held by its bridge alone: slides at $load N, mu F_cap = $mu_fcap N"
else
    fail "held: LAMMPS failed: $(grep -h -m1 ERROR "$log"*)"
fi

# the normal dashpot, c = 2 alpha sqrt(m_eff k_n), alpha = 0.3: the restitution of a head-on
# collision.  'dashpot both' (linear spring-dashpot): e = exp(-pi a / sqrt(1 - a^2));
# 'approach' (Richefeu 2007 eq. 3): damped to the deepest overlap, at t* with
# tan(w_d t*) = sqrt(1 - a^2) / a, then an undamped unloading: e = exp(-a w_0 t*)
for dashpot in both approach; do
    log="$TMP/collision_$dashpot.log"
    lmp 1 "$log" -in "$DECKS/in.collision" -var dashpot $dashpot -var alpha 0.3 >/dev/null 2>&1 ||
        { fail "collision $dashpot: LAMMPS failed: $(grep -h -m1 ERROR "$log"*)"; continue; }
    got=$(sed -n 's/^RESTITUTION //p' "$log" | head -1)
    expected=$(awk -v d=$dashpot 'BEGIN { a = 0.3; s = sqrt(1 - a * a); pi = atan2(0, -1)
        printf "%.17g", d == "both" ? exp(-pi * a / s) : exp(-a / s * atan2(s, a)) }')
    close_rel "collision, dashpot $dashpot: restitution" "$got" "$expected" 2e-3
    echo "collision, dashpot $dashpot: restitution $got, analytic $expected"
    # the same collision from a restart file written before it: the dashpot is one of the
    # pair style's settings stored there (the default, approach, would give the other e)
    # (lmp sets $log: the two logs are named before)
    restart="$TMP/collision_$dashpot.restart"
    write_log="$TMP/collision_${dashpot}_write.log" read_log="$TMP/collision_${dashpot}_read.log"
    if lmp 1 "$write_log" -in "$DECKS/in.collision" -var dashpot $dashpot -var alpha 0.3 \
        -var stage write -var restart_file "$restart" >/dev/null 2>&1 &&
        lmp 1 "$read_log" -in "$DECKS/in.collision" -var stage read \
            -var restart_file "$restart" >/dev/null 2>&1; then
        again=$(sed -n 's/^RESTITUTION //p' "$read_log" | head -1)
        close_rel "collision, dashpot $dashpot, from a restart file: restitution" "$again" "$got" 1e-9
        echo "collision, dashpot $dashpot, from a restart file: restitution $again"
    else
        fail "collision $dashpot, restart: LAMMPS failed: $(grep -h -m1 ERROR "$TMP/collision_${dashpot}_"*)"
    fi
done

# a restart file of the earlier settings format (written by the build before the contact
# law moved into the core: 'friction wet', the default then, and 'dashpot both' as the
# closing-rate floor -inf; tests/lammps/data/README): read with a warning naming the
# friction change, and the dashpot is 'both' (the restitution of a linear dashpot)
log="$TMP/old_restart.log"
if lmp 1 "$log" -in "$DECKS/in.collision" -var stage read \
    -var restart_file "$DECKS/data/friction_wet_dashpot_both.restart" >/dev/null 2>&1; then
    checks=$((checks + 1))
    grep -q "WARNING: pair gran/capillary: this restart file was written with 'friction wet'" "$log" ||
        fail "old restart file: no warning about 'friction wet'"
    close_rel "old restart file: restitution of dashpot both" "$(sed -n 's/^RESTITUTION //p' "$log" | head -1)" \
        "$(awk 'BEGIN { a = 0.3; s = sqrt(1 - a * a); printf "%.17g", exp(-atan2(0, -1) * a / s) }')" 2e-3
    echo "old restart file: $(grep -m1 '^RESTITUTION' "$log")"
else
    fail "old restart file: LAMMPS failed: $(grep -h -m1 ERROR "$log"*)"
fi

# the bridge's constants: gamma 0.0728 -> 0.05 between two runs, then sphere 2 grows to
# 1.5 times its diameter during a run (each force, in overlap, is the law's value at
# contact: Richefeu's 2 pi gamma R_g, which both changes move)
log="$TMP/rederive.log"
if lmp 1 "$log" -in "$DECKS/in.rederive" -var gamma1 0.0728 -var gamma2 0.05 -var growth 1.5 \
    >/dev/null 2>&1; then
    thermo "$log" >"$TMP/rows"
    n=0
    for expect in "0.0728 1e-3" "0.05 1e-3" "0.05 1.5e-3"; do
        n=$((n + 1))
        set -- $expect
        want=$("$CB" force richefeu gamma "$1" --r1 1e-3 --r2 "$2" --volume 1e-11 --gap -1e-4 |
            awk -F, 'NR == 2 { print $2 }')
        row=$(sed -n "${n}p" "$TMP/rows")
        [ $n = 3 ] && row=$(tail -n 1 "$TMP/rows")    # run 3: its last step
        for column in 2 3; do
            close_rel "bridge constants, run $n (gamma $1, r2 $2), $( [ $column = 2 ] &&
                echo 'force loop' || echo 'single()')" \
                "$(echo "$row" | awk -v c=$column '{ print $c }')" "$want" 1e-12
        done
        echo "bridge constants, run $n (gamma $1, r2 $2): LAMMPS $(echo "$row" | cut -d' ' -f2-), capbridge force $want"
    done
else
    fail "rederive: LAMMPS failed: $(grep -h -m1 ERROR "$log"*)"
fi

# the pair history's layout: a first run with no liquid keeps the tangential displacement
# alone (fix NEIGH_HISTORY_CAPILLARY_CONTACT0, 3 values a pair); the run that adds a volume
# widens it (NEIGH_HISTORY_CAPILLARY0, 10).  The spring loads on across the two runs:
# k_t |v| t = 100 * 0.01 * 100e-6 at step 100 (half that had it been lost), the bridge
# forms with 2 pi gamma R; on 1 rank, on 2 (the pair spans them), and through a restart
# file of the dry run
layout() {
    label=$1 np=$2 expected=$3
    shift 3
    log="$TMP/layout_$label.log"
    lmp "$np" "$log" -in "$DECKS/in.layout" "$@" >/dev/null 2>&1 ||
        { fail "layout $label: LAMMPS failed: $(grep -h -m1 ERROR "$log"*)"; return; }
    thermo "$log" >"$TMP/rows"
    close_rel "layout $label: tangential force at step 100" \
        "$(awk '$1 == 100 { print $3 }' "$TMP/rows")" 1e-4 1e-12
    close_rel "layout $label: capillary force at step 100" \
        "$(awk '$1 == 100 { print $2 }' "$TMP/rows")" "$FCAP" 1e-12
    checks=$((checks + 1))
    [ "$(sed -n 's/^Fix\[ *0\]: *\([A-Z_0-9]*\),.*/\1/p' "$log" | tr '\n' ' ')" = "$expected" ] ||
        fail "layout $label: history fixes '$(sed -n 's/^Fix\[ *0\]: *\([A-Z_0-9]*\),.*/\1/p' "$log" | tr '\n' ' ')', expected '$expected'"
    echo "layout $label: step 100 $(awk '$1 == 100' "$TMP/rows")"
}
layout one_rank 1 "NEIGH_HISTORY_CAPILLARY_CONTACT0 NEIGH_HISTORY_CAPILLARY0 "
layout two_ranks 2 "NEIGH_HISTORY_CAPILLARY_CONTACT0 NEIGH_HISTORY_CAPILLARY0 "
restart="$TMP/layout.restart"
if lmp 1 "$TMP/layout_write.log" -in "$DECKS/in.layout" -var stage write \
    -var restart_file "$restart" >/dev/null 2>&1; then
    layout restart 1 "NEIGH_HISTORY_CAPILLARY0 " -var stage read -var restart_file "$restart"
else
    fail "layout, restart: LAMMPS failed: $(grep -h -m1 ERROR "$TMP/layout_write.log"*)"
fi

# a volume changed between two runs applies to new bridges: a bridge of 1e-11 m^3 keeps its
# own rupture distance, (1e-11)^(1/3) = 215.4 um (sphere 2 moves 1 um a step from contact),
# whatever the new volume makes of the neighbor reach: lowered to 1e-13 (reach 46 um + skin)
# while in contact or when already stretched to 180 um (beyond the new reach plus the skin,
# where the setup's neighbor list had dropped it with its liquid), or to 0 (no new bridges)
rupture_step=$(awk 'BEGIN { d = exp(log(1e-11) / 3); for (i = 1; i * 1e-6 <= d; i++); print i }')
for case in 1e-13:0 1e-13:180 0:0; do
    small=${case%:*} before=${case#*:}
    log="$TMP/kept_${small}_$before.log"
    if lmp 1 "$log" -in "$DECKS/in.reach" -var small "$small" -var before "$before" \
        >/dev/null 2>&1; then
        thermo "$log" >"$TMP/rows"
        got=$(awk 'NF == 3 && $2 == 0 { print $1; exit }' "$TMP/rows")
        ruptured=$(awk -v s="$got" '$1 == s { print $3 }' "$TMP/rows" | tail -1)
        checks=$((checks + 1))
        [ "$got" = "$rupture_step" ] && [ "$ruptured" = 1 ] ||
            fail "volume $small after $before steps: the bridge went at step '$got' (ruptured '$ruptured'), expected its rupture at step $rupture_step"
        checks=$((checks + 1))
        ! grep -q "ruptured at the neighbor reach" "$log.screen" ||
            fail "volume $small after $before steps: a bridge was ruptured at the neighbor reach"
        echo "volume $small after $before steps: the bridge of 1e-11 m^3 ruptured at step $got (its rupture distance: step $rupture_step)"
    else
        fail "volume $small after $before steps: LAMMPS failed: $(grep -h -m1 ERROR "$log"*)"
    fi
done

# a bridge reaching the neighbor cutoff (here a sphere that grows during the run, so that
# the radii outgrow the reach built at the setup) is ruptured there, with a warning, before
# its pair leaves the list with its liquid
log="$TMP/grown.log"
if lmp 1 "$log" -in "$DECKS/in.reach" -var small 1e-11 -var before 0 -var grow 1.2 \
    >/dev/null 2>&1; then
    thermo "$log" >"$TMP/rows"
    list_cut=$(sed -n 's/.*master list distance cutoff = //p' "$log" | tail -1)
    expected=$(awk -v c="$list_cut" 'BEGIN { cut = c - 1e-4; for (i = 1; 2e-3 + i * 1e-6 < cut; i++); print i }')
    got=$(awk 'NF == 3 && $2 == 0 { print $1; exit }' "$TMP/rows")
    checks=$((checks + 1))
    [ "$got" = "$expected" ] ||
        fail "grown sphere: the bridge went at step '$got', expected step $expected (the reach)"
    checks=$((checks + 1))
    grep -q "1 bridge(s) ruptured at the neighbor reach" "$log.screen" ||
        fail "grown sphere: no warning of a bridge ruptured at the neighbor reach"
    echo "grown sphere: the bridge ruptured at step $got, at the reach (list cutoff $list_cut m)"
else
    fail "grown sphere: LAMMPS failed: $(grep -h -m1 ERROR "$log"*)"
fi

# the neighbor reach
reach() {
    label=$1 expected=$2
    shift 2
    log="$TMP/reach_$label.log"
    lmp 1 "$log" -in "$DECKS/in.contact" -var overlap 0 -var vy 0 -var nsteps 0 "$@" \
        >/dev/null 2>&1 || { fail "reach $label: LAMMPS failed: $(grep -h -m1 ERROR "$log"*)"; return; }
    got=$(sed -n 's/.*master list distance cutoff = //p' "$log" | head -1)
    close_rel "reach $label: neighbor cutoff" "$got" "$expected" 1e-7
    echo "reach $label: neighbor cutoff $got m, r1 + r2 + 1.05 rupture distance + skin = $expected m"
}
# richefeu: rupture distance (1 + theta/2) V^(1/3) (Lian, Richefeu 2007 eq. 6), the reach 5 %
# beyond it (the core's CB_REACH_MARGIN); skin 1e-4
reach fixed "$(awk 'BEGIN { printf "%.17g", 2e-3 + 1.05 * exp(log(1e-11) / 3) + 1e-4 }')" -var vkw "volume 1e-11"
reach protocol2 "$(awk 'BEGIN { printf "%.17g", 2e-3 + 1.05 * exp(log(3e-11) / 3) + 1e-4 }')" \
    -var vkw " " -var fixmode protocol2 -var fixargs "liquid 1e-11 vmax 3e-11"
reach dry "$(awk 'BEGIN { printf "%.17g", 2e-3 + 1e-4 }')" -var vkw "volume 0"

finish
