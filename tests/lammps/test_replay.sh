#!/bin/sh
# Replay: the wet granular packing (in.granular, 2000 spheres, 300 steps) dumps every
# pair within reach every 50 steps (dump local of compute pair/local: capillary force,
# gap, bridge volume, bridge flag, r1, r2, printed with 17 digits); `capbridge replay`
# recomputes the force of every row with the same law: the largest relative difference
# must stay below 1e-12.  Several laws and liquid modes, 1 and 2 ranks, and
# pair_style hybrid/overlay (granular + gran/capillary contact none).
. "$(dirname "$0")/lib.sh" "$@"

scene_data "$TMP/scene.data" 10 10 20 13579 0.3

# replay_case LABEL NP NEWTON STYLE MODE LIQUID PERATOM LAW...
replay_case() {
    label=$1 np=$2 newton=$3 style=$4 mode=$5 liquid=$6 peratom=$7
    shift 7
    law="$*"
    lmp "$np" "$TMP/$label.log" -in "$DECKS/in.granular" -var DECKS "$DECKS" \
        -var data "$TMP/scene.data" -var newton "$newton" -var style "$style" -var mode "$mode" \
        -var liquid "$liquid" -var peratom "$peratom" -var law "$law" -var nsteps 300 \
        -var every 50 -var local 50 -var out "$TMP/$label" >/dev/null 2>&1 ||
        { fail "$label: LAMMPS failed: $(grep -h -m1 ERROR "$TMP/$label.log"*)"; return; }
    checks=$((checks + 1))
    # shellcheck disable=SC2086 # the law is words
    if ! "$CB" replay $law --columns force=1,gap=2,volume=3,r1=5,r2=6 --tolerance 1e-12 \
        "$TMP/$label.local" >"$TMP/$label.replay" 2>"$TMP/$label.err"; then
        fail "$label: capbridge replay: $(cat "$TMP/$label.err") $(cat "$TMP/$label.replay")"
        return
    fi
    checks=$((checks + 1))
    awk -F, -v label="$label" 'NR == 2 {
        printf "%s: %d rows, %d bridges, largest relative difference %s\n", label, $1, $2, $3
        exit !($2 >= 5000 && $3 < 1e-12) }' "$TMP/$label.replay" ||
        fail "$label: replay result $(tail -1 "$TMP/$label.replay") (expected >= 5000 bridges)"
}

replay_case richefeu_p2 1 on own protocol2 "water 0.01 1000" 1 richefeu gamma 0.0728
replay_case willett_p3_np2 2 off own protocol3 "water 0.01 1000" 1 willett gamma 0.0728 theta 20
replay_case soulie_fixed 1 on own none " " 0 soulie gamma 0.0728 theta 10
replay_case rabinovich_p1_hybrid 1 on hybrid protocol1 "water 0.02 1000 every 100" 0 rabinovich gamma 0.0728
replay_case weigert_p2_hybrid_np2 2 on hybrid protocol2 "water 0.005 1000" 1 weigert gamma 0.0728 theta 5

finish
