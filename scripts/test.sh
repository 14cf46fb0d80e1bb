#!/usr/bin/env bash
# Runs every capbridge test: the C core, CLI and reference-data tests (gcc, -Werror), the
# LAMMPS plugin and LIGGGHTS model tests against engines built once into the cache outside the
# repository (scripts/build_lammps.sh, scripts/build_liggghts.sh: a cached build is reused),
# then the C tests again under AddressSanitizer + UndefinedBehaviorSanitizer (clang), with the
# libFuzzer target over the force API for a bounded time.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top"
scripts/configure.sh
jobs=$(nproc)

CC=clang cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DCAPBRIDGE_SANITIZE=ON \
  -DCAPBRIDGE_FUZZ=ON >/dev/null
cmake --build build-asan -j "$jobs"

export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export ASAN_OPTIONS=detect_leaks=1
status=0
(cd build-asan && ctest --output-on-failure -L sanitized -j "$jobs") || status=1
(cd build && ctest --output-on-failure -j "$jobs") || status=1
exit $status
