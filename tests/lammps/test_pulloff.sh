#!/bin/sh
# Pull-off of two spheres for the 13 setups of Gladkyy & Schwarze 2014, Table 1 (the
# laws in turn, several options), two contact cases with damping, and two through
# pair_style hybrid/overlay granular + gran/capillary contact none: at every step the
# LAMMPS curve (x1, v1, gap, capillary force, contact force, bridge) equals the one of
# `capbridge pulloff` (its step order mirrors fix nve + fix move) to 1e-9 relative.
# Lengths near zero (x1, gap) are differences of coordinates of size r1 + r2: they are
# compared to 1e-9 relative with a floor of 1e-5 (r1 + r2), i.e. an absolute tolerance of
# 1e-14 (r1 + r2), some tens of units in the last place of the coordinates (LAMMPS applies
# the force as del (F / r), the reference as F: they differ in the last bit, and in a
# long contact the trajectories drift apart by a few units in the last place); the
# contact force (k_n times the overlap) gets the same floor times k_n, the velocity of
# sphere 1 a floor of the pulling velocity.  With damping the contact force
# that compute pair/local reports is evaluated with the velocities at output time (the
# end of the step), the force loop with the half-step ones (velocity Verlet): the
# trajectory (x1, v1 at every step) checks the damped force, the column is not compared.
. "$(dirname "$0")/lib.sh" "$@"

# compare REF LOG LABEL R1+R2 KN DAMPED VELOCITY: every reference row against LAMMPS's
compare() {
    checks=$((checks + 1))
    thermo "$2" >"$TMP/rows"
    awk -F, -v label="$3" -v rows="$TMP/rows" -v rsum="$4" -v kn="$5" -v damped="$6" -v vel="$7" '
    function abs(x) { return x < 0 ? -x : x }
    function same(name, got, want, floor_,   s) {
        s = abs(want); if (s < floor_) s = floor_
        if (s > 0 && abs(got - want) / s > worst) { worst = abs(got - want) / s; worst_at = name " at step " step }
        if (abs(got - want) <= 1e-9 * s) return
        if (bad < 5) printf "%s step %d: %s LAMMPS %.17g, capbridge %.17g\n", label, step, name, got, want
        bad++
    }
    BEGIN { while ((getline line < rows) > 0) { n = split(line, f, " "); row[f[1]] = line; count++ } }
    /^#/ && /^# rupture_distance/ { d = $0; sub(/.*= /, "", d) }
    /^#/ || $1 == "step" { next }
    {
        step = $1; refs++
        if (!(step in row)) { if (bad < 5) printf "%s: no LAMMPS row for step %d\n", label, step; bad++; next }
        split(row[step], f, " ")
        same("time", f[2], $2, 1e-300)
        same("x1", f[3], $3, 1e-5 * rsum); same("v1", f[4], $4, vel)
        same("x2", f[5], $5, 1e-300); same("gap", f[6], $6, 1e-5 * rsum)
        same("capillary_force", f[7], $7, 1e-300)
        if (!damped) same("contact_force", f[8], $8, 1e-5 * rsum * kn)
        if (f[9] + 0 != $9 + 0) { if (bad < 5) printf "%s step %d: bridge %s, capbridge %s\n", label, step, f[9], $9; bad++ }
        if ($9 == 1) bridged++; if ($9 == 0 && bridged) broken++
        if ($8 > 0) contacts++
    }
    END {
        if (refs < 100) { printf "%s: only %d reference rows\n", label, refs; bad++ }
        if (count != refs) { printf "%s: %d LAMMPS rows, %d reference rows\n", label, count, refs; bad++ }
        printf "%s: %d steps compared, %d with a bridge, %d after rupture, %d in contact; largest relative difference %.3g (%s)\n", label, refs, bridged, broken, contacts, worst, worst_at
        exit bad > 0 }' "$1" >"$TMP/why" || { fail "$(cat "$TMP/why")"; return; }
    cat "$TMP/why"
}

# case NAME R1 R2 VOLUME VELOCITY LAW...  [env: STYLE, DAMPING, MAXSTEPS, NEWTON, KN]
case_run() {
    name=$1 r1=$2 r2=$3 vol=$4 v=$5
    shift 5
    law="$*"
    extra=""
    [ -n "${MAXSTEPS:-}" ] && extra="--max-steps $MAXSTEPS"
    # shellcheck disable=SC2086
    "$CB" pulloff $law --r1 "$r1" --r2 "$r2" --volume "$vol" --velocity "$v" \
        --kn "${KN:-1e3}" --damping "${DAMPING:-0}" $extra >"$TMP/$name.csv" 2>"$TMP/$name.err"
    code=$?
    if [ -z "${MAXSTEPS:-}" ] && [ "$code" -ne 0 ]; then
        fail "$name: capbridge pulloff exit $code: $(cat "$TMP/$name.err")"
        return
    fi
    dt=$(awk '/^# dt = / { print $4 }' "$TMP/$name.csv")
    nsteps=$(awk -F, '!/^#/ && $1 != "step" { s = $1 } END { print s }' "$TMP/$name.csv")
    geo=$(awk -v a="$r1" -v b="$r2" 'BEGIN { printf "%.17g %.17g %.17g", 2 * a, 2 * b, a + b }')
    set -- $geo
    lmp 1 "$TMP/$name.log" -in "$DECKS/in.pulloff" -var style "${STYLE:-own}" \
        -var newton "${NEWTON:-on}" -var law "$law" -var r1 "$r1" -var r2 "$r2" \
        -var d1 "$1" -var d2 "$2" -var xstart2 "$3" -var rho 2500 -var kn "${KN:-1e3}" \
        -var alpha "${DAMPING:-0}" -var vol "$vol" -var v "$v" -var dt "$dt" \
        -var nsteps "$nsteps" -var skin "$r2" -var half "$(awk -v s="$3" 'BEGIN { print 10 * s }')" \
        >/dev/null 2>&1 ||
        { fail "$name: LAMMPS failed: $(grep -m1 ERROR "$TMP/$name.log.screen")"; return; }
    damped=$(awk -v a="${DAMPING:-0}" 'BEGIN { print (a > 0) }')
    compare "$TMP/$name.csv" "$TMP/$name.log" "$name" "$3" "${KN:-1e3}" "$damped" "$v"
}

W=20.6e-3
# Gladkyy 2014 Table 1 (src_c/cli/cases.c): W = Willett 2000, R = Rabinovich 2005
case_run W11 2.381e-3 2.381e-3 13.6e-12 0.1 richefeu gamma $W
case_run W12 2.381e-3 2.381e-3 31.3e-12 0.1 willett gamma $W
case_run W13 2.381e-3 2.381e-3 74.2e-12 0.1 willett/reduced gamma $W
case_run W21 2.381e-3 1.588e-3 9.6e-12 0.1 rabinovich gamma $W
case_run W22 2.381e-3 1.588e-3 13.2e-12 0.1 rabinovich/uncorrected gamma $W
case_run W23 2.381e-3 1.588e-3 24.7e-12 0.1 weigert gamma $W
case_run W24 2.381e-3 1.588e-3 59.3e-12 0.1 soulie gamma $W
case_run W31 2.381e-3 1.191e-3 25.3e-12 0.1 richefeu gamma $W rupture willett overlap none
case_run W32 2.381e-3 1.191e-3 61.8e-12 0.1 willett gamma $W rupture lian
case_run W33 2.381e-3 1.191e-3 127.8e-12 0.1 table gamma $W
case_run R1 19e-6 35e-6 2e-19 1 rabinovich gamma 27e-3 theta 10
case_run R2 19e-6 32.5e-6 12e-19 1 willett gamma 24e-3 theta 10
NEWTON=off case_run R3 19e-6 27.5e-6 36e-19 1 richefeu gamma 28e-3 theta 10 c 0.8
# contact and damping: slow pulls, sphere 1 caught by sphere 2 (no rupture: --max-steps)
MAXSTEPS=3000 case_run contact0 1e-3 1e-3 1e-11 1e-4 richefeu gamma 0.0728
MAXSTEPS=3000 DAMPING=0.5 case_run contact5 1e-3 1e-3 1e-11 1e-4 willett gamma 0.0728
# capillary only, on top of LAMMPS's own granular pair style (no contact in a pull-off)
STYLE=hybrid case_run hybridW12 2.381e-3 2.381e-3 31.3e-12 0.1 willett gamma $W
STYLE=hybrid NEWTON=off case_run hybridR1 19e-6 35e-6 2e-19 1 rabinovich gamma 27e-3 theta 10

finish
