#!/bin/sh
# Regenerates a sample of reference_data/ (cases, grid, plane) with the exact solver and
# compares it with the
# stored rows: every number to 1e-9 relative (the solver converges far below that, so a
# larger difference means the data or the solver changed).
# usage: reference_sample.sh CAPBRIDGE_BINARY REFERENCE_DIR
set -eu
bin=$1
dir=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

compare() { # set name
  "$bin" reference "$1" --only "$2" | grep -v '^#' | grep -v '^case,' > "$tmp/new.csv"
  grep "^$2," "$dir/$1.csv" > "$tmp/stored.csv" || { echo "no rows for $2 in $1.csv"; exit 1; }
  awk -F, -v name="$2" '
    NR == FNR { for (i = 2; i <= NF; ++i) stored[FNR, i] = $i; rows = FNR; next }
    {
      for (i = 2; i <= NF; ++i) {
        a = $i + 0; b = stored[FNR, i] + 0
        scale = (b < 0 ? -b : b); if (scale < 1e-300) scale = 1
        d = (a - b) / scale; if (d < 0) d = -d
        if (d > worst) worst = d
      }
      n = FNR
    }
    END {
      if (n != rows || n != 21) { printf "%s: %d new rows, %d stored\n", name, n, rows; exit 1 }
      printf "%s: 21 rows, largest relative difference %.3g\n", name, worst
      exit (worst <= 1e-9) ? 0 : 1
    }' "$tmp/stored.csv" "$tmp/new.csv"
}

compare cases W21
compare cases R3
compare grid t30_r3_v0.001
compare grid t0_r10_v0.1
compare plane t20_plane_v0.001
compare plane t40_plane_v0.1
