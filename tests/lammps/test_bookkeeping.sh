#!/bin/sh
# The liquid's bookkeeping across runs and commands (in.bookkeeping): nothing gained or
# lost silently.
#   clear:    write_restart, clear, read_restart in one process: every bridge and the total
#             come back (the pair history's fix ID does not depend on the pair instance)
#   existing: bridges formed with fixed volumes before fix capillary/liquid protocol2
#             'liquid 1e-9 start free' are part of that total, and a warning says so
#   changed:  a restart file read with another water content keeps the file's total, and
#             a warning says so
#   deleted:  delete_atoms between two runs (Protocol 2): a warning names the change
#   narrow:   bridges in a periodic box narrower than twice the neighbor cutoff: an error
. "$(dirname "$0")/lib.sh" "$@"

scene_data "$TMP/scene.data" 6 6 6 13579 1.0
scene_data "$TMP/narrow.data" 6 2 6 13579 1.0

run_case() {    # run_case CASE [DATA]: LAMMPS's exit status
    lmp 1 "$TMP/$1.log" -in "$DECKS/in.bookkeeping" -var case "$1" \
        -var data "${2:-$TMP/scene.data}" -var out "$TMP/bookkeeping" >/dev/null 2>&1
}
run_ok() {    # run_ok CASE [DATA]: LAMMPS ran; else a failure naming its error
    checks=$((checks + 1))
    run_case "$@" && return 0
    fail "$1: LAMMPS failed: $(grep -m1 ERROR "$TMP/$1.log")"
    return 1
}
# printed NAME LOG: the values after "NAME " in the deck's print line
printed() { sed -n "s/^$1 //p" "$2" | head -1; }
has() {    # has LABEL LOG PATTERN
    checks=$((checks + 1))
    grep -Eq "$3" "$2" || fail "$1: no line matching '$3' in $2"
}

if run_ok clear; then
    set -- $(printed BEFORE "$TMP/clear.log")
    bridges=$1 total=$2
    set -- $(printed AFTER "$TMP/clear.log")
    checks=$((checks + 1))
    [ "${bridges:-0}" -gt 0 ] && [ "$1" = "$bridges" ] ||
        fail "clear: $bridges bridges before clear, ${1:-none} after read_restart"
    close_rel "clear: total liquid after read_restart" "$2" "$total" 1e-12
    echo "clear: $bridges bridges, total $total, back after clear + read_restart"
fi

if run_ok existing; then
    has existing "$TMP/existing.log" "WARNING: fix capillary/liquid protocol2: [0-9]+ bridges holding .* exist at the start of the liquid"
    set -- $(printed AFTER "$TMP/existing.log")
    close_rel "existing: total liquid with the bridges that existed" "$2" 1e-9 1e-12
    echo "existing: $(grep -m1 'exist at the start' "$TMP/existing.log")"
fi

if run_ok changed; then
    has changed "$TMP/changed.log" "WARNING: fix capillary/liquid protocol2: the restart file's total liquid .* is kept"
    set -- $(printed AFTER "$TMP/changed.log")
    close_rel "changed: the file's total is kept" "$2" "$total" 1e-12
fi

if run_ok deleted; then
    has deleted "$TMP/deleted.log" "WARNING: fix capillary/liquid protocol2: the liquid changed by -[0-9.e+-]+ .* between two runs"
fi

checks=$((checks + 1))
if run_case narrow "$TMP/narrow.data"; then
    fail "narrow: LAMMPS succeeded; expected the periodic box error"
else
    has narrow "$TMP/narrow.log" "ERROR: pair gran/capillary: the periodic box is 0.00224 wide along y, less than twice the neighbor cutoff"
fi

finish
