#!/bin/sh
# Two builds of the LAMMPS plugin against each other on one side of the benchmark scene
# (bench/in.cycle.lammps, 16 000 grains, 2000 steps; the wet side unless SIDE says off),
# measured as part 1 of bench/run.sh measures: both runs at the same time, pinned to one
# core, each holding it until both timed runs are done (the deck's me/partner), and their
# CPU times compared; the launch order alternates.  Prints, per repeat, B's CPU time over
# A's.  Run A against A first: its spread bounds what a comparison can resolve.  A may be
# the word stock: LAMMPS's own gran/hooke/history (the deck's stock side), so that a build
# made for a measurement (bench/README.md, "where the wet side's time goes") is compared
# with the dry style as part 1 compares the plugin.  A developer's tool for a change to the
# hot path; not a test.
# Usage: bench/compare_builds.sh A.so|stock B.so [REPEATS, default 4] [SIDE: wet (default) | off]
# (copy build/lammps_pair/lammps/capbridgeplugin.so aside before rebuilding for B)
set -eu
[ $# -ge 2 ] || { echo "usage: $0 A.so|stock B.so [REPEATS] [wet|off]" >&2; exit 2; }
for build in "$1" "$2"; do
    [ "$build" = stock ] || [ -f "$build" ] ||
        { echo "$0: no plugin file '$build' (a .so, or stock for A)" >&2; exit 2; }
done
[ "$2" != stock ] || { echo "$0: B must be a plugin build; stock is allowed as A only" >&2; exit 2; }
a=$1 b=$(realpath "$2") repeats=${3:-4} scene_side=${4:-wet}
[ "$a" = stock ] || a=$(realpath "$a")
case $scene_side in wet | off) ;; *) echo "$0: SIDE must be wet or off, not '$scene_side'" >&2; exit 2 ;; esac
top=$(cd "$(dirname "$0")/.." && pwd)
cache=${CAPBRIDGE_CACHE:-$HOME/.cache/capbridge}
. "$cache/lammps-20250204/lammps.env"
work=$top/out/bench/compare
mkdir -p "$work"
cd "$work"
[ -f base.data ] || "$LAMMPS_BINARY" -in "$top/bench/in.cycle.lammps" -var stage prep \
    -var data base.data -log none -screen none
# side PLUGIN|stock NAME PARTNER: one run on core 0, its log NAME.log (run in the
# background, the subshell becomes the engine: its PID is the one to stop)
side() {
    if [ "$1" = stock ]; then run_side=stock; else run_side=$scene_side; fi
    exec taskset -c 0 "$LAMMPS_BINARY" -in "$top/bench/in.cycle.lammps" -var data base.data \
        -var side "$run_side" -var plugin "$1" -var nx 2 -var ny 2 -var nz 2 -var steps 2000 \
        -var me "$2" -var partner "$3" -log "$2.log" -screen none
}
# the first run's CPU time: its loop time times its CPU use
cpu_seconds() {
    awk '/^Loop time/ && !l { l = $4 } /% CPU use/ && !c { c = $1 + 0 }
         END { print l * c / 100 }' "$1"
}
for r in $(seq 1 "$repeats"); do
    rm -f A.done B.done
    if [ $((r % 2)) = 1 ]; then
        side "$a" A B & pa=$!; side "$b" B A & pb=$!
    else
        side "$b" B A & pb=$!; side "$a" A B & pa=$!
    fi
    # a run that fails never marks itself done: when the first of the two ends, a failure
    # stops its partner (the deck's own limit, 10 x the steps, is the backstop)
    while kill -0 "$pa" 2>/dev/null && kill -0 "$pb" 2>/dev/null; do sleep 1; done
    for build in A B; do
        if [ "$build" = A ]; then pid=$pa partner=$pb; else pid=$pb partner=$pa; fi
        kill -0 "$pid" 2>/dev/null && continue
        if ! wait "$pid"; then
            kill "$partner" 2>/dev/null
            echo "$0: the run of build $build failed, see $work/$build.log" >&2
            exit 1
        fi
    done
    wait "$pa" && wait "$pb" || { echo "$0: a run failed, see $work/A.log, B.log" >&2; exit 1; }
    echo "$(cpu_seconds A.log) $(cpu_seconds B.log)" |
        awk -v r="$r" '{ printf "repeat %d: B/A CPU time %.3f (%.2f s / %.2f s)\n",
                                r, $2 / $1, $2, $1 }'
done
