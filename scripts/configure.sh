#!/usr/bin/env bash
# Installs the Debian packages, builds (or reuses) LAMMPS and LIGGGHTS in the cache outside the
# repository, and configures and builds capbridge in build/ with both bindings: the C core, the
# CLI, the LAMMPS plugin (build/lammps_pair/lammps/capbridgeplugin.so) and the tests.
# Used by run.sh, test.sh and scene.sh; prints nothing but errors and the compiler's output.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top"
scripts/setup_deps.sh
cache=${CAPBRIDGE_CACHE:-$HOME/.cache/capbridge}
scripts/build_lammps.sh >/dev/null
scripts/build_liggghts.sh >/dev/null
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release \
  -DCAPBRIDGE_LAMMPS_ENV="$cache/lammps-20250204/lammps.env" \
  -DCAPBRIDGE_LIGGGHTS_ENV="$cache/liggghts-3.8.0/liggghts.env" >/dev/null
cmake --build build -j "$(nproc)" >/dev/null
