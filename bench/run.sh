#!/usr/bin/env bash
# The benchmarks of issue 6 (bench/bench.py: what each part measures): set-up as the README's
# commands (scripts/configure.sh; CAPBRIDGE_SKIP_CONFIGURE=1 skips it), then every part.
# Usage: bench/run.sh [--parts 1,2,3,4] [--repeats N] [--quick]
#        bench/run.sh --compare A.so|stock B.so [--side wet|off] [--options-a WORDS]
#                     [--repeats N]  (two builds; no set-up: the builds are given)
# About 25 minutes on 2 idle cores; run it on a quiet machine (the figures are ratios measured
# in one run, but a busy machine still widens their spread). Writes bench/README.md.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top"
compare=0
for arg in "$@"; do case $arg in --compare) compare=1 ;; esac; done
[ "${CAPBRIDGE_SKIP_CONFIGURE:-0}" = 1 ] || [ "$compare" = 1 ] || scripts/configure.sh
exec /usr/bin/python3 bench/bench.py "$@"
