#!/usr/bin/env bash
# The main job: builds everything (scripts/configure.sh), then compresses a wet granular cylinder
# (Richefeu 2007 section 4.2, default size: 3000 glass beads, w = 2 %, Protocol 1) and the same
# sample dry, in LAMMPS under mpirun -np 2, and prints the compressive strengths
# (out/uniaxial/main/: strength.csv, stress.png, strength.png, snapshot.png). Under a minute
# on 2 quiet cores once the engines are built. The law report: build/src_c/cli/capbridge report.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top"
scripts/configure.sh
out=out/uniaxial/main
export CAPBRIDGE_SKIP_CONFIGURE=1
for run in wet dry; do
  echo "capbridge: uniaxial compression, $run (LAMMPS, -np 2, size default; log $out/$run/log.lammps)"
  extra=()
  [ "$run" = dry ] && extra=(-var dry yes -var travel 0.5e-3)  # dry: a short travel shows sigma ~ 0
  # w = 2 % (the decks take the water content in percent of the grains' mass, as the paper)
  scripts/scene.sh lammps uniaxial -np 2 -size default -out "$out/$run" -var w 2 "${extra[@]}" >/dev/null
done
/usr/bin/python3 inputs/uniaxial/post.py "$out" "$out/wet" "$out/dry"
echo "capbridge: wrote $out/stress.png, $out/strength.png, $out/snapshot.png, $out/strength.csv"
