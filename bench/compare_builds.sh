#!/bin/sh
# Two builds of the LAMMPS plugin against each other on the wet side of the benchmark scene
# (bench/in.cycle.lammps, 16 000 grains, 2000 steps), run at the same time, one on each of
# the two cores: the machine's drift falls on both, which alternating runs do not achieve on
# a noisy virtual machine.  Prints, per repeat, B's pair and loop time over A's.  Run A
# against A first: the spread and bias of that control (here 1.02-1.06) bound what a
# comparison can resolve.  A developer's tool for a change to the hot path; not a test.
# Usage: bench/compare_builds.sh A.so B.so [REPEATS, default 4]
# (copy build/lammps_pair/lammps/capbridgeplugin.so aside before rebuilding for B)
set -eu
[ $# -ge 2 ] || { echo "usage: $0 A.so B.so [REPEATS]" >&2; exit 2; }
a=$(realpath "$1") b=$(realpath "$2") repeats=${3:-4}
top=$(cd "$(dirname "$0")/.." && pwd)
cache=${CAPBRIDGE_CACHE:-$HOME/.cache/capbridge}
. "$cache/lammps-20250204/lammps.env"
work=$top/out/bench/compare
mkdir -p "$work"
cd "$work"
[ -f base.data ] || "$LAMMPS_BINARY" -in "$top/bench/in.cycle.lammps" -var stage prep \
    -var data base.data -log none -screen none
side() {
    "$LAMMPS_BINARY" -in "$top/bench/in.cycle.lammps" -var data base.data -var side wet \
        -var plugin "$1" -var nx 2 -var ny 2 -var nz 2 -var steps 2000 -log "$2" -screen none
}
pair_and_loop() {
    awk '/^Pair / { p = $3 } /^Loop time/ { l = $4 } END { print p, l }' "$1"
}
for r in $(seq 1 "$repeats"); do
    side "$a" log.A & side "$b" log.B & wait
    echo "$(pair_and_loop log.A) $(pair_and_loop log.B)" |
        awk -v r="$r" '{ printf "repeat %d: B/A pair %.3f, loop %.3f\n", r, $3 / $1, $4 / $2 }'
done
