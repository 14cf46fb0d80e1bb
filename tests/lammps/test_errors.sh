#!/bin/sh
# Bad input, one test each: LAMMPS stops with an error whose message names the problem (a
# corrupted restart file too); and the time-step check warns once, with the numbers.
. "$(dirname "$0")/lib.sh" "$@"

GOOD="100 40 0.3 0.4 law richefeu gamma 0.0728 volume 1e-12"
# expect NAME PATTERN PAIR_STYLE PAIR_COEFF [FIXMODE [FIXARGS [FIXMODIFY [WALLARGS]]]]: LAMMPS
# fails, its ERROR line matches PATTERN (an extended regular expression); WALLARGS: the
# arguments of a fix capillary/wall
expect() {
    name=$1 pattern=$2
    checks=$((checks + 1))
    lmp 1 "$TMP/$name.log" -in "$DECKS/in.errors" -var pstyle "$3" -var pcoeff "$4" \
        -var fixmode "${5:-none}" -var fixargs "${6:- }" \
        -var fixmodify_on "$([ -n "${7:-}" ] && echo 1 || echo 0)" -var fixmodify "${7:- }" \
        -var wall_on "$([ -n "${8:-}" ] && echo 1 || echo 0)" -var wallargs "${8:- }" >/dev/null 2>&1
    code=$?
    line=$(grep -h -m1 'ERROR' "$TMP/$name.log" "$TMP/$name.log.screen" 2>/dev/null | head -1)
    if [ "$code" -eq 0 ]; then
        fail "$name: LAMMPS succeeded; expected an error matching '$pattern'"
    elif ! printf '%s\n' "$line" | grep -Eq "$pattern"; then
        fail "$name: exit $code, error '$line' does not match '$pattern'"
    else
        echo "$name: $line"
    fi
}

# fix capillary/wall
expect wall_style "fix capillary/wall: unknown wall style 'ycylinder': allowed xplane, yplane, zplane, zcylinder, region" \
    gran/capillary "$GOOD" none " " "" "ycylinder 0.001 NULL NULL"
expect wall_cylinder_radius "fix capillary/wall: zcylinder radius -0.004 must be > 0 and finite" \
    gran/capillary "$GOOD" none " " "" "zcylinder -0.004"
expect wall_cylinder_args "fix capillary/wall: expected 'xplane\|yplane\|zplane LO HI' \(LO or HI may be NULL\), 'zcylinder RADIUS' or 'region REGION-ID'" \
    gran/capillary "$GOOD" none " " "" "zcylinder"
expect wall_region "fix capillary/wall: region nowhere does not exist: define it with the region command before this fix" \
    gran/capillary "$GOOD" none " " "" "region nowhere"
expect wall_both_null "fix capillary/wall: both LO and HI are NULL" \
    gran/capillary "$GOOD" none " " "" "zplane NULL NULL"
expect wall_order "fix capillary/wall: LO 0.005 must be below HI -0.005" \
    gran/capillary "$GOOD" none " " "" "xplane 0.005 -0.005"
expect wall_angle "fix capillary/wall: angle 95: the wall's contact angle must be in 0 <= angle < 90" \
    gran/capillary "$GOOD" none " " "" "zplane -0.001 NULL angle 95"
expect wall_volume "fix capillary/wall: volume -1: a bridge volume must be > 0" \
    gran/capillary "$GOOD" none " " "" "zplane -0.001 NULL volume -1"
expect wall_keyword "fix capillary/wall: unknown keyword 'height': allowed angle, volume" \
    gran/capillary "$GOOD" none " " "" "zplane -0.001 NULL height 2"
expect wall_value "fix capillary/wall: keyword 'angle' needs a value" \
    gran/capillary "$GOOD" none " " "" "zplane -0.001 NULL angle"
expect wall_angle_protocol1 "fix capillary/wall: keyword angle with fix capillary/liquid protocol1: Protocol 1 distributes the liquid with one law" \
    gran/capillary "100 40 0.3 0.4 law richefeu gamma 0.0728" protocol1 "liquid 1e-11" "" "zplane -0.001 NULL angle 30"
expect wall_volume_protocol "fix capillary/wall: keyword volume is for liquid mode fixed" \
    gran/capillary "100 40 0.3 0.4 law richefeu gamma 0.0728" protocol2 "liquid 1e-11" "" "zplane -0.001 NULL volume 1e-12"
expect wall_pair "fix capillary/wall requires pair style gran/capillary" \
    "gran/hooke/history 100 40 0.3 0.4 0.5 1" "" none " " "" "zplane -0.001 NULL"
expect unknown_keyword "unknown keyword 'foo': allowed gamma, theta, rupture, overlap, validity, viscosity, min_gap, c" \
    gran/capillary "100 40 0.3 0.4 law richefeu gamma 0.0728 foo 1"
expect viscosity_without_min_gap "viscosity 0.001 needs min_gap" \
    gran/capillary "100 40 0.3 0.4 law richefeu gamma 0.0728 viscosity 1e-3"
expect repeated_law_keyword "keyword 'gamma' given twice: each law keyword may be given once" \
    gran/capillary "100 40 0.3 0.4 law richefeu gamma 0.0728 gamma 0.02 volume 1e-12"
expect repeated_volume "keyword 'volume' given twice: each keyword may be given once" \
    gran/capillary "100 40 0.3 0.4 law richefeu gamma 0.0728 volume 1e-12 volume 2e-12"
expect repeated_style_keyword "pair_style gran/capillary: keyword 'dashpot' given twice" \
    "gran/capillary dashpot both dashpot approach" "$GOOD"
expect unknown_law "unknown law 'richefoo': allowed richefeu, willett" \
    gran/capillary "100 40 0.3 0.4 law richefoo gamma 0.0728 volume 1e-12"
expect unknown_style_keyword "pair_style gran/capillary: unknown keyword 'frictoin'" \
    "gran/capillary frictoin wet" "$GOOD"
expect unknown_dashpot "pair_style gran/capillary: dashpot 'sometimes': allowed approach, both" \
    "gran/capillary dashpot sometimes" "$GOOD"
expect missing_coefficient "missing coefficient mu \(friction coefficient\) before 'law'" \
    gran/capillary "100 40 0.3 law richefeu gamma 0.0728 volume 1e-12"
expect missing_gamma "law richefeu needs 'gamma' \(the surface tension, force/distance\)" \
    gran/capillary "100 40 0.3 0.4 law richefeu volume 1e-12"
expect missing_volume "pair_coeff 1 1: no bridge volume: give 'volume V'" \
    gran/capillary "100 40 0.3 0.4 law richefeu gamma 0.0728"
expect negative_volume "volume = -1e-12: the bridge volume must be >= 0" \
    gran/capillary "100 40 0.3 0.4 law richefeu gamma 0.0728 volume -1e-12"
expect negative_gamma "surface tension gamma = -0.0728: must be > 0" \
    gran/capillary "100 40 0.3 0.4 law willett gamma -0.0728 volume 1e-12"
expect theta_90 "contact angle theta = 90 degrees: allowed 0 <= theta < 90 degrees" \
    gran/capillary "100 40 0.3 0.4 law rabinovich gamma 0.0728 theta 90 volume 1e-12"
expect damping_range "damping = 1.5: the damping rate alpha_n must lie in \[0, 1\]" \
    gran/capillary "100 40 1.5 0.4 law richefeu gamma 0.0728 volume 1e-12"
expect fix_without_pair "fix capillary/liquid requires pair style gran/capillary" \
    "gran/hooke/history 100 NULL 0 NULL 0.4 0" "" protocol2 "water 0.01 1000"
expect hybrid_twice "pair gran/capillary can be used once: as the pair style, or as one sub-style of pair_style hybrid/overlay" \
    "hybrid/overlay gran/capillary gran/capillary" "gran/capillary 1 $GOOD"
expect fix_fixed_not_a_volume "fix capillary/liquid fixed: volume 'nan' is not a number" \
    gran/capillary "$GOOD" fixed nan
expect fix_unknown_keyword "fix capillary/liquid: unknown keyword 'wather'" \
    gran/capillary "100 40 0.3 0.4 law richefeu gamma 0.0728" protocol2 "wather 0.01 1000"
expect fix_unknown_mode "fix capillary/liquid: unknown mode 'protocol4'" \
    gran/capillary "100 40 0.3 0.4 law richefeu gamma 0.0728" protocol4 "water 0.01 1000"
expect fix_no_liquid "fix capillary/liquid protocol1: give the liquid once" \
    gran/capillary "100 40 0.3 0.4 law richefeu gamma 0.0728" protocol1 "every 10"
expect fix_volume_conflict "volume 1e-12 conflicts with fix capillary/liquid protocol2" \
    gran/capillary "$GOOD" protocol2 "water 0.01 1000"
W="100 40 0.3 0.4 law richefeu gamma 0.0728"
expect fix_remove_protocol1 "keyword 'remove' applies to protocol2 and protocol3 only \(Protocol 1 gives every eligible pair a bridge again" \
    gran/capillary "$W" protocol1 "water 0.01 1000 remove 0.5 7"
expect fix_remove_fixed "keyword 'remove' applies to protocol2 and protocol3 only \(fixed volumes keep no water content" \
    gran/capillary "$W" fixed "1e-12 remove 0.5 7"
expect fix_remove_start_free "keyword 'remove' needs 'start bridges'" \
    gran/capillary "$W" protocol2 "water 0.01 1000 remove 0.5 7 start free"
expect fix_remove_fraction "remove 1.5: the share of the bridges removed must be > 0 and <= 1" \
    gran/capillary "$W" protocol3 "water 0.01 1000 remove 1.5 7"
expect fix_remove_zero "remove 0: the share of the bridges removed must be > 0 and <= 1" \
    gran/capillary "$W" protocol2 "water 0.01 1000 remove 0 7"
expect fix_remove_seed "remove seed 0: must be a whole number >= 1" \
    gran/capillary "$W" protocol2 "water 0.01 1000 remove 0.5 0"
expect fix_remove_values "keyword 'remove' needs 2 values" \
    gran/capillary "$W" protocol2 "water 0.01 1000 remove 0.5"
expect fix_modify_remove_protocol1 "fix_modify remove applies to protocol2 and protocol3 only \(Protocol 1" \
    gran/capillary "$W" protocol1 "water 0.01 1000" "remove 0.5 7"
expect fix_modify_remove_start_free "fix_modify remove needs 'start bridges'" \
    gran/capillary "$W" protocol2 "water 0.01 1000 start free" "remove 0.5 7"
expect fix_modify_remove_values "fix_modify liq remove: needs 2 values, F SEED" \
    gran/capillary "$W" protocol3 "water 0.01 1000" "remove 0.5"
expect fix_modify_remove_seed "remove seed -3: must be a whole number >= 1" \
    gran/capillary "$W" protocol2 "water 0.01 1000" "remove 0.5 -3"

# two atoms at the same position: an error naming them before any force is applied (no NaN
# pressure in thermo output first)
checks=$((checks + 1))
lmp 1 "$TMP/coincident.log" -in "$DECKS/in.errors" -var pstyle gran/capillary \
    -var pcoeff "$GOOD" -var x2 0 >/dev/null 2>&1 && fail "coincident: LAMMPS succeeded"
grep -q "ERROR.*pair gran/capillary: atoms 1 and 2 are at the same position (0, 0, 0)" \
    "$TMP/coincident.log" "$TMP/coincident.log.screen" 2>/dev/null ||
    fail "coincident: no error naming atoms 1 and 2: $(grep -h -m1 ERROR "$TMP/coincident.log")"
! grep -qi "nan" "$TMP/coincident.log" || fail "coincident: a NaN was printed before the error"
echo "coincident: $(grep -h -m1 ERROR "$TMP/coincident.log" "$TMP/coincident.log.screen" 2>/dev/null | head -1)"

# a restart file whose pair history holds a corrupted bridge: refused at the first force
# pass of the run that reads it, with an error naming the pair (the held path of the pair
# loop reads only the fields it uses, so the state is checked once, where it enters).
# patch_bridges FILE OFFSET BYTES: in every active bridge of volume 1e-11 in FILE (the
# volume's 8 bytes then those of active = 1.0, little-endian), overwrite the 8 bytes OFFSET
# bytes after the volume's with BYTES (printf's octal escapes); prints how many
patch_bridges() {
    found=$(od -A d -v -t x1 "$1" | awk -v pattern="956479e17ffda53d000000000000f03f" '
        { for (k = 2; k <= NF; k++) byte[n++] = $k }
        END { for (p = 0; p + 16 <= n; p++) {
                  s = ""; for (q = 0; q < 16; q++) s = s byte[p + q]
                  if (s == pattern) print p } }')
    for start in $found; do
        # shellcheck disable=SC2059 # the bytes are the format: its octal escapes
        printf "$3" | dd of="$1" bs=1 seek=$((start + $2)) conv=notrunc 2>/dev/null
    done
    echo "$found" | awk 'NF { n++ } END { print n + 0 }'
}
lmp 1 "$TMP/corrupt_write.log" -in "$DECKS/in.corrupt" -var file "$TMP/bridge.restart" \
    >/dev/null 2>&1 || fail "corrupt: writing the restart file failed: $(grep -m1 ERROR "$TMP/corrupt_write.log")"
# corrupt_case NAME OFFSET BYTES FIELD: FIELD (the state's field at OFFSET) set to BYTES
corrupt_case() {
    checks=$((checks + 1))
    cp "$TMP/bridge.restart" "$TMP/$1.restart"
    patched=$(patch_bridges "$TMP/$1.restart" "$2" "$3")
    # the bridge is in the history of both its atoms
    [ "$patched" -eq 2 ] || { fail "$1: $patched bridges found in the restart file, expected 2"; return; }
    lmp 1 "$TMP/$1.log" -in "$DECKS/in.corrupt" -var stage read -var file "$TMP/$1.restart" \
        >/dev/null 2>&1 && { fail "$1: LAMMPS read the corrupted restart file and ran"; return; }
    line=$(grep -h -m1 'ERROR' "$TMP/$1.log" "$TMP/$1.log.screen" 2>/dev/null | head -1)
    printf '%s\n' "$line" | grep -Eq "pair history of atoms (1 and 2|2 and 1) holds no valid bridge state \(.*$4.*\): the stored bridge state is not a valid bridge" ||
        { fail "$1: error '$line' does not name the pair and its state"; return; }
    echo "$1: $line"
}
corrupt_case corrupt_active 8 '\000\000\000\000\000\000\340\077' "active 0.5"
# a field the held path does not read in contact: refused all the same
corrupt_case corrupt_law_constant 48 '\000\000\000\000\000\000\360\277' "law constant -1"

# the time-step check: dt = 1e-3 s is far above 10 % of pi sqrt(m/k_n) (about 1.6e-4 s)
checks=$((checks + 1))
lmp 1 "$TMP/dt.log" -in "$DECKS/in.errors" -var pstyle gran/capillary -var pcoeff "$GOOD" \
    -var dt 1e-3 >/dev/null 2>&1 || fail "time step: LAMMPS failed: $(grep -m1 ERROR "$TMP/dt.log")"
count=$(grep -c 'WARNING: pair gran/capillary: time step 0.001 s exceeds the limit' "$TMP/dt.log")
[ "$count" -eq 1 ] || fail "time step: $count warnings, expected 1"
limit=$(sed -n 's/.*exceeds the limit \([^ ]*\) s = 10% of pi sqrt(m\/k).*/\1/p' "$TMP/dt.log" | head -1)
# m = 4/3 pi (1 mm)^3 2500 kg/m^3, k = k_n = 100 N/m: 0.1 pi sqrt(m/k)
close_rel "time step: 0.1 pi sqrt(m/k) in the warning" "$limit" \
    "$(awk 'BEGIN { pi = atan2(0, -1); m = 4 / 3 * pi * 1e-9 * 2500; printf "%.17g", 0.1 * pi * sqrt(m / 100) }')" 1e-5
echo "time step: $(grep -m1 'WARNING: pair gran/capillary' "$TMP/dt.log")"

# a bridge larger than the spheres (1 m^3 between millimetre spheres): a warning
checks=$((checks + 1))
lmp 1 "$TMP/huge.log" -in "$DECKS/in.errors" -var pstyle gran/capillary \
    -var pcoeff "100 40 0.3 0.4 law richefeu gamma 0.0728 volume 1" >/dev/null 2>&1 ||
    fail "huge volume: LAMMPS failed: $(grep -m1 ERROR "$TMP/huge.log")"
grep -q "WARNING: pair gran/capillary: types 1 1: a bridge of volume 1 ruptures at 1, beyond the radius sum 0.002" "$TMP/huge.log" ||
    fail "huge volume: no warning: $(grep -m1 WARNING "$TMP/huge.log")"
echo "huge volume: $(grep -m1 'WARNING: pair gran/capillary: types' "$TMP/huge.log")"

# k_n = 1 N/m: the capillary stiffness bound decides.  Richefeu's law is steepest at contact,
# so the bound is |dF/dgap| at gap 0, which the CLI's force curve gives independently
checks=$((checks + 1))
lmp 1 "$TMP/dt_capillary.log" -in "$DECKS/in.errors" -var pstyle gran/capillary \
    -var pcoeff "1 0.4 0.3 0.4 law richefeu gamma 0.0728 volume 1e-12" -var dt 1e-3 \
    >/dev/null 2>&1 || fail "capillary time step: LAMMPS failed: $(grep -m1 ERROR "$TMP/dt_capillary.log")"
bound=$(sed -n 's/.*the capillary stiffness bound \([^)]*\)).*/\1/p' "$TMP/dt_capillary.log" | head -1)
at_contact=$("$CB" curve richefeu --r1 1e-3 --r2 1e-3 --volume 1e-12 --points 2 --to 1e-6 |
    awk -F, 'NR == 2 { printf "%.17g", $3 < 0 ? -$3 : $3 }')
close_rel "capillary time step: the stiffness bound in the warning" "$bound" "$at_contact" 1e-5
echo "capillary time step: $(grep -m1 'WARNING: pair gran/capillary' "$TMP/dt_capillary.log")"

finish
