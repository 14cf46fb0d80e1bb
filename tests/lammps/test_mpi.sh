#!/bin/sh
# The wet granular packing (in.granular, 2000 spheres) on 1, 2 and 3 ranks, newton on
# and off, for Protocols 2, 3 and 1, and on 2 ranks through pair_style hybrid/overlay:
#  - at every output the total liquid (fix capillary/liquid, element 8: (total -
#    initial) / initial) is conserved to 1e-12 relative;
#  - the fix's census agrees with an independent sum: the bridge count and the liquid in
#    bridges with compute pair/local (p4, p3, summed over all pairs), the free liquid with
#    the per-atom free liquid of the fix (Protocols 2, 3);
#  - over the 200 steps (20 outputs) every run has the same bridge count at every output
#    as the 1-rank newton-on run, and the same liquid in bridges to 1e-9 relative.
. "$(dirname "$0")/lib.sh" "$@"

scene_data "$TMP/scene.data" 10 10 20 12345 0.3
STEPS=200

# check_run LOG MODE: conservation and the independent census at every output
check_run() {
    checks=$((checks + 1))
    thermo "$1" | awk -v label="$(basename "$1" .log)" -v peratom="$2" '
    function abs(x) { return x < 0 ? -x : x }
    function rel(a, b,   s) { s = abs(b); if (s == 0) s = 1; return abs(a - b) / s }
    {
        rows++
        # 1 step 2 atoms 3 bridges 4 z 5 bridged 6 free 7 total 8 formed 9 ruptured
        # 10 change 11 pair/local bridges 12 pair/local liquid 13 per-atom free liquid
        if (abs($10) > 1e-12) { printf "%s step %s: total liquid changed by %.3g (relative)\n", label, $1, $10; bad++ }
        if (abs($10) > worst) worst = abs($10)
        if ($3 != $11) { printf "%s step %s: fix counts %s bridges, pair/local %s\n", label, $1, $3, $11; bad++ }
        if (rel($5, $12) > 1e-12) { printf "%s step %s: liquid in bridges %.17g, pair/local %.17g\n", label, $1, $5, $12; bad++ }
        if (peratom && rel($6, $13) > 1e-12) { printf "%s step %s: free liquid %.17g, per-atom sum %.17g\n", label, $1, $6, $13; bad++ }
        formed += $8; ruptured += $9
    }
    END {
        if (rows < 21) { printf "%s: %d outputs\n", label, rows; bad++ }
        if (formed < 50 || ruptured < 50) { printf "%s: only %d formations, %d ruptures\n", label, formed, ruptured; bad++ }
        printf "%s: %d outputs, %d formations, %d ruptures, largest relative change of the total liquid %.3g\n", label, rows, formed, ruptured, worst
        exit bad > 0 }' >"$TMP/why" || { fail "$(head -5 "$TMP/why")"; return; }
    cat "$TMP/why"
}

# same_as REF LOG: identical bridge counts, liquid in bridges and free liquid to 1e-9
same_as() {
    checks=$((checks + 1))
    thermo "$1" >"$TMP/ref.rows"
    thermo "$2" | awk -v label="$(basename "$2" .log) vs $(basename "$1" .log)" -v ref="$TMP/ref.rows" '
    function abs(x) { return x < 0 ? -x : x }
    function rel(a, b,   s) { s = abs(b); if (s == 0) s = 1e-300; return abs(a - b) / s }
    BEGIN { while ((getline line < ref) > 0) { split(line, f, " "); nb[f[1]] = f[3]; vb[f[1]] = f[5]; fr[f[1]] = f[6] } }
    {
        rows++
        if (!($1 in nb)) { printf "%s: no reference row for step %s\n", label, $1; bad++; next }
        if ($3 != nb[$1]) { printf "%s step %s: %s bridges, reference %s\n", label, $1, $3, nb[$1]; bad++ }
        d = rel($5, vb[$1]); if (d > worst) worst = d
        if (d > 1e-9) { printf "%s step %s: liquid in bridges %.17g, reference %.17g\n", label, $1, $5, vb[$1]; bad++ }
        if (fr[$1] > 0) { d = rel($6, fr[$1]); if (d > worst) worst = d }
    }
    END {
        printf "%s: %d outputs with the same bridges; liquid differs by %.3g (relative) at most\n", label, rows, worst
        exit bad > 0 }' >"$TMP/why" || { fail "$(head -5 "$TMP/why")"; return; }
    cat "$TMP/why"
}

run_mode() {
    mode=$1 liquid=$2 peratom=$3 style=${4:-own}
    ref=""
    for newton in on off; do
        for np in 1 2 3; do
            [ "$style" = hybrid ] && [ "$np" -ne 2 ] && continue
            log="$TMP/${mode}_${style}_np${np}_newton${newton}.log"
            if ! lmp "$np" "$log" -in "$DECKS/in.granular" -var DECKS "$DECKS" \
                -var data "$TMP/scene.data" -var newton "$newton" -var mode "$mode" \
                -var liquid "$liquid" -var peratom "$peratom" -var style "$style" \
                -var nsteps "$STEPS" -var every 10 -var out "$TMP/out" >/dev/null 2>&1; then
                fail "$(basename "$log"): LAMMPS failed: $(grep -h -m1 ERROR "$log" "$log.screen")"
                continue
            fi
            check_run "$log" "$peratom"
            if [ -z "$ref" ]; then ref=$log; else same_as "$ref" "$log"; fi
        done
    done
}

run_mode protocol2 "water 0.01 1000" 1
run_mode protocol3 "water 0.01 1000" 1
run_mode protocol1 "water 0.01 1000 every 50" 0
run_mode protocol2 "water 0.01 1000" 1 hybrid

finish
