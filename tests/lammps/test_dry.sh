#!/bin/sh
# A scene without liquid pays for its contacts only: pair gran/capillary with volume 0
# everywhere uses LAMMPS's per-pair size neighbor list and skips dry pairs that are apart
# without a square root. With no damping its contact law is that of LAMMPS's own
# gran/hooke/history (k_n overlap; tangential spring, Coulomb limit mu f_n), so the two must
# give the same trajectories of a colliding packing, up to round-off (the Coulomb limit is
# mu k_n overlap here and mu |k_n overlap / r| r there), on 1 and on 2 ranks.
. "$(dirname "$0")/lib.sh" "$@"

scene_data "$TMP/scene.data" 12 12 12 4711 0.3
for run in stock:1 own:1 own:2; do
    style=${run%:*} np=${run#*:}
    lmp "$np" "$TMP/$style-$np.log" -in "$DECKS/in.dry" -var data "$TMP/scene.data" \
        -var style "$style" -var nsteps 400 -var out "$TMP/$style-$np.dump" >/dev/null 2>&1 ||
        fail "$style on $np ranks: LAMMPS failed: $(grep -h -m1 ERROR "$TMP/$style-$np.log"*)"
done
neighbors() { sed -n 's/^Ave neighs\/atom = //p' "$1" | tail -1; }
checks=$((checks + 1))
[ "$(neighbors "$TMP/own-1.log")" = "$(neighbors "$TMP/stock-1.log")" ] ||
    fail "neighbor lists differ: $(neighbors "$TMP/own-1.log") pairs per atom, stock $(neighbors "$TMP/stock-1.log")"

# compare DUMP_A DUMP_B: the largest position difference [m], the largest force difference
# relative to the largest force, and the largest force [N] (> 0: there were contacts)
compare() {
    awk 'FNR == 1 { file++ } /^ITEM: ATOMS/ { on = 1; next } /^ITEM/ { on = 0 }
         on && file == 1 { for (k = 2; k <= 10; k++) a[$1, k] = $k; n++ }
         on && file == 2 { for (k = 2; k <= 4; k++) { d = $k - a[$1, k]; if (d < 0) d = -d; if (d > dx) dx = d }
                           for (k = 8; k <= 10; k++) { d = $k - a[$1, k]; if (d < 0) d = -d; if (d > df) df = d
                                                       f = ($k < 0) ? -$k : $k; if (f > fmax) fmax = f } }
         END { printf "%.3g %.3g %.3g\n", dx, (fmax > 0) ? df / fmax : 1, fmax }' "$1" "$2"
}
for other in own-1 own-2; do
    set -- $(compare "$TMP/stock-1.dump" "$TMP/$other.dump")
    echo "$other against stock-1: positions differ by at most $1 m, forces by $2 of the largest force ($3 N)"
    checks=$((checks + 3))
    awk -v f="$3" 'BEGIN { exit !(f > 1e-3) }' || fail "$other: largest force $3 N: no contacts to compare"
    awk -v d="$1" 'BEGIN { exit !(d <= 1e-12) }' || fail "$other: positions differ by $1 m (tolerance 1e-12 m, 1e-9 of a diameter)"
    awk -v d="$2" 'BEGIN { exit !(d <= 1e-9) }' || fail "$other: forces differ by $2 of the largest (tolerance 1e-9)"
done
finish
