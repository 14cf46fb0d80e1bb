# lib.sh — shared helpers of the LAMMPS binding tests (POSIX sh + awk).
# Source it as:   . "$(dirname "$0")/lib.sh" "$@"
# with the arguments every test script gets from ctest:
#   $1 path of lammps.env (scripts/build_lammps.sh)   $2 capbridgeplugin.so, or "none"
#                                                        for a LAMMPS with the styles built in
#   $3 the capbridge CLI                              $4 the directory of the decks
ENV_FILE=${1:?"usage: $0 lammps.env capbridgeplugin.so capbridge DECK_DIR"}
PLUGIN=${2:?"missing capbridgeplugin.so"}
CB=${3:?"missing capbridge CLI"}
DECKS=${4:-$(dirname "$0")}
[ -f "$ENV_FILE" ] || { echo "$0: no env file '$ENV_FILE'" >&2; exit 2; }
[ "$PLUGIN" = none ] || [ -f "$PLUGIN" ] || { echo "$0: no plugin '$PLUGIN'" >&2; exit 2; }
[ -x "$CB" ] || { echo "$0: '$CB' is not an executable" >&2; exit 2; }
# the env file holds KEY=VALUE lines (LAMMPS_BINARY, LAMMPS_MPIRUN, ...)
set -a
# shellcheck disable=SC1090
. "$ENV_FILE"
set +a
LMP=${LAMMPS_BINARY:?"$ENV_FILE sets no LAMMPS_BINARY"}
MPIRUN=${LAMMPS_MPIRUN:-mpirun}
TMP=$(mktemp -d "${TMPDIR:-/tmp}/capbridge-lammps.XXXXXX") || exit 2
if [ -n "${CAPBRIDGE_KEEP_TMP:-}" ]; then
    echo "$(basename "$0"): keeping $TMP" >&2
else
    trap 'rm -rf "$TMP"' EXIT
fi
trap 'exit 2' INT TERM
# Open MPI: run as root inside containers, and do not bind the oversubscribed ranks
export OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_hwloc_base_binding_policy=none
checks=0
failures=0

fail() {
    echo "FAIL: $*" >&2
    failures=$((failures + 1))
}

finish() {
    echo "$(basename "$0"): $checks checks, $failures failed"
    [ "$failures" -eq 0 ]
}

# lmp NP LOG -in DECK -var ...: run LAMMPS on NP ranks (1: no mpirun), log to LOG.
# Returns LAMMPS's exit status; the screen output goes to LOG.screen.  The decks load
# the plugin when plugin_load is yes (a LAMMPS Boolean cannot compare a path).
lmp() {
    np=$1
    log=$2
    shift 2
    load=yes
    [ "$PLUGIN" = none ] && load=no
    if [ "$np" -eq 1 ]; then
        "$LMP" -log "$log" -screen "$log.screen" -nocite -var plugin "$PLUGIN" \
            -var plugin_load $load "$@"
    else
        # shellcheck disable=SC2086 # MPIRUN is a command with options
        $MPIRUN -np "$np" "$LMP" -log "$log" -screen "$log.screen" -nocite \
            -var plugin "$PLUGIN" -var plugin_load $load "$@" </dev/null
    fi
}

# thermo LOG: the thermo rows of every run in LOG (lines of numbers after a "Step" header)
thermo() {
    awk '/^ *Step / { on = 1; next } /^Loop time/ { on = 0 } on && $1 ~ /^[0-9]+$/' "$1"
}

# close_rel LABEL ACTUAL EXPECTED TOLERANCE: |actual - expected| <= tol |expected|
close_rel() {
    checks=$((checks + 1))
    awk -v a="$2" -v e="$3" -v t="$4" 'BEGIN {
        if (a == "" || e == "") exit 1
        d = a - e; if (d < 0) d = -d
        s = e < 0 ? -e : e; if (s == 0) s = 1
        exit !(d <= t * s) }' || fail "$1: got '$2', expected '$3' (relative tolerance $4)"
}

# The granular scene: N spheres (radii 0.45..0.55 mm) on a jittered cubic lattice of
# spacing 1.12 mm in a periodic box, written as a LAMMPS data file (atom_style sphere).
# Park-Miller generator in awk (exact in doubles): the same file with every awk.
# scene_data FILE NX NY NZ SEED [VMAX: random velocities in -VMAX..VMAX m/s, default 0.1]
#            [SHIFT: the lattice moved by SHIFT spacings along x, y, z and wrapped into the
#            box, default 0; 0.5 puts lattice planes on the box faces and on the faces of
#            evenly split subdomains, which atoms then cross all the time]
#            [SPACING: the lattice spacing [m], default 1.12e-3 (no two spheres touch);
#            0.95e-3 makes most neighbours overlap]
scene_data() {
    awk -v nx="$2" -v ny="$3" -v nz="$4" -v seed="$5" -v vmax="${6:-0.1}" -v shift="${7:-0}" \
        -v a="${8:-1.12e-3}" '
    function wrap(x, l) { return x >= l ? x - l : (x < 0 ? x + l : x) }
    function rnd() { seed = (16807 * seed) % 2147483647; return seed / 2147483647 }
    BEGIN {
        n = nx * ny * nz
        printf "capbridge granular scene: %d x %d x %d spheres\n\n", nx, ny, nz
        printf "%d atoms\n1 atom types\n\n", n
        printf "0 %.17g xlo xhi\n0 %.17g ylo yhi\n0 %.17g zlo zhi\n\n", nx * a, ny * a, nz * a
        print "Atoms # sphere\n"
        id = 0
        for (k = 0; k < nz; k++) for (j = 0; j < ny; j++) for (i = 0; i < nx; i++) {
            id++
            d = 2 * (0.45e-3 + 0.1e-3 * rnd())
            x = wrap((i + 0.5 + shift) * a + 0.02e-3 * (2 * rnd() - 1), nx * a)
            y = wrap((j + 0.5 + shift) * a + 0.02e-3 * (2 * rnd() - 1), ny * a)
            z = wrap((k + 0.5 + shift) * a + 0.02e-3 * (2 * rnd() - 1), nz * a)
            printf "%d 1 %.17g 2500 %.17g %.17g %.17g\n", id, d, x, y, z
        }
        print "\nVelocities\n"
        for (id = 1; id <= n; id++)
            printf "%d %.17g %.17g %.17g 0 0 0\n", id, vmax * (2 * rnd() - 1),
                   vmax * (2 * rnd() - 1), vmax * (2 * rnd() - 1)
    }' >"$1"
}
