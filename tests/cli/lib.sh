# lib.sh — shared helpers of the CLI tests (POSIX sh + awk). Source it with the path of
# the capbridge binary as $1:   . "$(dirname "$0")/lib.sh"
CB=${1:?"usage: $0 path/to/capbridge"}
[ -x "$CB" ] || { echo "$0: '$CB' is not an executable" >&2; exit 2; }
TMP=$(mktemp -d "${TMPDIR:-/tmp}/capbridge-cli.XXXXXX") || exit 2
trap 'rm -rf "$TMP"' EXIT
trap 'exit 2' INT TERM
checks=0
failures=0

fail() {
    echo "FAIL: $*" >&2
    failures=$((failures + 1))
}

# close_rel LABEL ACTUAL EXPECTED TOLERANCE: |actual - expected| <= tol |expected|
# (<= tol when expected is 0)
close_rel() {
    checks=$((checks + 1))
    awk -v a="$2" -v e="$3" -v t="$4" 'BEGIN {
        if (a == "" || e == "") exit 1
        d = a - e; if (d < 0) d = -d
        s = e < 0 ? -e : e; if (s == 0) s = 1
        exit !(d <= t * s) }' || fail "$1: got '$2', expected '$3' (relative tolerance $4)"
}

# field FILE ROW COLUMN: a CSV field, ROW counted over the lines that are not comments
field() {
    awk -F, -v r="$2" -v c="$3" '/^#/ { next } { n++ } n == r { print $c; exit }' "$1"
}

finish() {
    echo "$(basename "$0"): $checks checks, $failures failed"
    [ "$failures" -eq 0 ]
}

# Richefeu et al. 2007 computed by hand, independently of the core (awk functions):
#   F = 2 pi gamma cos(theta) sqrt(R1 R2) exp(-a / lambda)                 eqs. 4, 5, 7, 10
#   lambda = c / sqrt(2) V^(1/2) max(R1/R2, R2/R1)^(-1/2) (1/R1 + 1/R2)^(1/2)   eq. 11
#   rupture distance (1 + theta/2) V^(1/3), theta in rad                    eq. 6
# the contact value in overlap (overlap contact), 0 beyond the rupture distance.
# shellcheck disable=SC2034 # used by the scripts that source this file
RICHEFEU_AWK='
function rf_pi() { return atan2(0, -1) }
function rf_lambda(r1, r2, v, c,   ratio) {
    ratio = r1 > r2 ? r1 / r2 : r2 / r1
    return c / sqrt(2) * sqrt(v) * ratio ^ (-0.5) * sqrt(1 / r1 + 1 / r2)
}
function rf_rupture(v, theta_deg) {
    return (1 + theta_deg * rf_pi() / 180 / 2) * exp(log(v) / 3)
}
function rf_force(r1, r2, v, a, gamma, theta_deg, c) {
    if (a > rf_rupture(v, theta_deg)) return 0
    if (a < 0) a = 0
    return 2 * rf_pi() * gamma * cos(theta_deg * rf_pi() / 180) * sqrt(r1 * r2) * \
           exp(-a / rf_lambda(r1, r2, v, c))
}
function rf_abs(x) { return x < 0 ? -x : x }
# 1 if |a - e| <= t max(|e|, floor)
function rf_close(a, e, t, floor_,   s) {
    s = rf_abs(e); if (s < floor_) s = floor_
    return rf_abs(a - e) <= t * s
}
'
