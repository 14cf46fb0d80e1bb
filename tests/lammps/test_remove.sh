#!/bin/sh
# Keyword remove of fix capillary/liquid (Richefeu 2007 fig. 7, fig. 12: half of the bonds
# removed, the water content kept), on the wet granular packing (in.granular, its lattice
# closer than the diameters: most pairs in contact), Protocols 2 and 3, on 1, 2 and 3 ranks with newton on and off:
#  - the run without remove has M bridges at step 0; with remove 0.5 the fix reports N of
#    them removed, N within 4 standard deviations of M/2 (a binomial draw), and M - N
#    bridges remain at step 0; the same N and the same bridges on every decomposition;
#  - the removed liquid is handed on by the protocol: Protocol 2, every drop of it is free
#    liquid at step 0 (to 1e-12 relative); Protocol 3, more liquid stays in bridges than
#    the remaining bridges held before (the receivers grew); the total is conserved to
#    1e-12 at every output;
#  - a removed pair in contact forms no bridge again while its contact lasts: M - N
#    bridges at step 0 and few formations in the next 10 steps (< N / 5: new contacts as
#    the packing relaxes).  Without the mark (cb_bridge_remove made to leave none) 2557
#    of the 2999 removed bridges formed again at step 0 (5558 bridges, not 3001).
#  - fix_modify liq remove 0.5 7723 between two runs (the half bonds after a consolidation,
#    Richefeu fig. 7): the first run is the run without remove, step for step; the removal
#    comes at the second run's start and not before (its message after the first run's
#    loop), N' of the M' bridges of the first run's end, N' within 4 standard deviations
#    of M'/2, M' - N' + formed - ruptured bridges at the second run's start, the same on
#    1 and 2 ranks, the liquid kept.
. "$(dirname "$0")/lib.sh" "$@"

# a lattice closer than the diameters, at rest: most bridges are in contact at the start
scene_data "$TMP/scene.data" 10 10 20 12345 0 0 0.95e-3

# rows LOG: step bridges bridged free total formed ruptured change (thermo columns 1 3 5-10)
rows() { thermo "$1" | awk '{ print $1, $3, $5, $6, $7, $8, $9, $10 }'; }

# same_counts LABEL LOG FILE: LOG's bridge counts per step are FILE's; the first call (FILE
# missing) writes FILE
same_counts() {
    rows "$2" | awk '{ print $1, $2 }' >"$TMP/counts"
    if [ ! -f "$3" ]; then cp "$TMP/counts" "$3"; return; fi
    checks=$((checks + 1))
    cmp -s "$TMP/counts" "$3" || fail "$1: bridge counts differ from the first decomposition's"
}

run() {  # run LOG NP NEWTON MODE LIQUID [LATER]
    lmp "$2" "$1" -in "$DECKS/in.granular" -var DECKS "$DECKS" -var data "$TMP/scene.data" \
        -var newton "$3" -var mode "$4" -var liquid "$5" -var later "${6:-0}" -var peratom 1 -var nsteps 100 \
        -var every 10 -var out "$TMP/out" >/dev/null 2>&1 ||
        { fail "$(basename "$1"): LAMMPS failed: $(grep -h -m1 ERROR "$1" "$1.screen")"; return 1; }
}

for mode in protocol2 protocol3; do
    run "$TMP/$mode-all.log" 1 on $mode "water 0.01 1000" || continue
    all=$(rows "$TMP/$mode-all.log" | awk 'NR == 1 { print $2, $3 }')
    for newton in on off; do
        for np in 1 2 3; do
            log="$TMP/$mode-np$np-newton$newton.log"
            run "$log" $np $newton $mode "water 0.01 1000 remove 0.5 7723" || continue
            checks=$((checks + 1))
            removed=$(grep -h -m1 "removed .* of .* bridges" "$log" | sed 's/.*removed \([0-9]*\) of \([0-9]*\) bridges.*holding \([^ ]*\) of.*/\1 \2 \3/')
            [ -n "$removed" ] || { fail "$mode np $np newton $newton: no removal message"; continue; }
            rows "$log" | awk -v label="$mode np $np newton $newton" -v all="$all" \
                -v removed="$removed" -v mode=$mode '
            function abs(x) { return x < 0 ? -x : x }
            BEGIN { split(all, a, " "); split(removed, r, " "); m = a[1]; n = r[1] }
            {
                if (abs($8) > 1e-12) { printf "%s step %s: total liquid changed by %.3g\n", label, $1, $8; bad++ }
                if (NR == 1) { b0 = $2; f0 = $6; bridged0 = $3; free0 = $4 }
                if (NR == 2) early = $6 - f0
            }
            END {
                if (r[2] != m) { printf "%s: the fix saw %s bridges, the run without remove %s\n", label, r[2], m; bad++ }
                if (abs(n - m / 2) > 4 * sqrt(m / 4)) { printf "%s: removed %s of %s\n", label, n, m; bad++ }
                if (b0 != m - n) { printf "%s: %s bridges at step 0, expected %s - %s\n", label, b0, m, n; bad++ }
                if (mode == "protocol2" && abs(free0 - r[3]) > 1e-12 * r[3]) { printf "%s: free liquid %.17g at step 0, removed %.17g\n", label, free0, r[3]; bad++ }
                if (mode == "protocol3" && !(bridged0 > a[2] - r[3] * (1 + 1e-12))) { printf "%s: %.17g in bridges, no receiver grew (%.17g - %.17g)\n", label, bridged0, a[2], r[3]; bad++ }
                if (!(early < n / 5)) { printf "%s: %s bridges formed in the first 10 steps after removing %s\n", label, early, n; bad++ }
                printf "%s: removed %s of %s bridges, %s formed in the next 10 steps, liquid kept\n", label, n, m, early
                exit bad > 0 }' >"$TMP/why" || { fail "$(head -5 "$TMP/why")"; continue; }
            cat "$TMP/why"
            same_counts "$mode np $np newton $newton" "$log" "$TMP/$mode.counts"
        done
    done
done

# fix_modify remove between two runs (rows of the second run follow the first run's 11)
for mode in protocol2 protocol3; do
    rows "$TMP/$mode-all.log" | awk '{ print $1, $2 }' >"$TMP/$mode-all.counts"
    for np in 1 2; do
        log="$TMP/$mode-later-np$np.log"
        run "$log" $np on $mode "water 0.01 1000" 0.5 || continue
        checks=$((checks + 1))
        rows "$log" | awk 'NR <= 11 { print $1, $2 }' | cmp -s - "$TMP/$mode-all.counts" ||
            fail "$mode later np $np: the first run differs from the run without remove"
        awk '/^Loop time/ { loops++ } /removed .* of .* bridges/ { print loops + 0; exit }' "$log" |
            grep -qx 1 || fail "$mode later np $np: the removal message is not after the first run's loop"
        removed=$(grep -h -m1 "removed .* of .* bridges" "$log" | sed 's/.*removed \([0-9]*\) of \([0-9]*\) bridges.*/\1 \2/')
        [ -n "$removed" ] || { fail "$mode later np $np: no removal message"; continue; }
        rows "$log" | awk -v label="$mode later np $np" -v removed="$removed" '
        function abs(x) { return x < 0 ? -x : x }
        BEGIN { split(removed, r, " "); n = r[1] }
        {
            if (abs($8) > 1e-12) { printf "%s step %s: total liquid changed by %.3g\n", label, $1, $8; bad++ }
            if (NR == 11) { m = $2; f = $6; u = $7 }
            if (NR == 12) { b = $2; df = $6 - f; du = $7 - u }
        }
        END {
            if (r[2] != m) { printf "%s: the fix saw %s bridges, the first run ended with %s\n", label, r[2], m; bad++ }
            if (abs(n - m / 2) > 4 * sqrt(m / 4)) { printf "%s: removed %s of %s\n", label, n, m; bad++ }
            if (b != m - n + df - du) { printf "%s: %s bridges at the second start, expected %s - %s + %s - %s\n", label, b, m, n, df, du; bad++ }
            printf "%s: removed %s of %s bridges at the second run, liquid kept\n", label, n, m
            exit bad > 0 }' >"$TMP/why" || { fail "$(head -5 "$TMP/why")"; continue; }
        cat "$TMP/why"
        same_counts "$mode later np $np" "$log" "$TMP/$mode-later.counts"
    done
done
finish
