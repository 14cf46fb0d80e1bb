#!/usr/bin/env bash
# The runs of docs/results/uniaxial.md: uniaxial compression (Richefeu 2007 section 4.2) for
# w = 2, 4, 6 % under Protocols 1, 2 and 3 in each engine, half of the bridges removed (w = 2
# and 4 %, Protocol 2: LAMMPS fix capillary/liquid remove 0.5, LIGGGHTS the model's remove
# 0.5, both with the draw of seed 7723), and dry; then post.py.
# w is in percent of the grains' mass, as the decks take it (-var w 2 = 2 %).
# Usage: inputs/uniaxial/study.sh [-seed N] [smoke|default|paper] [lammps] [liggghts]
#   (default: smoke, both engines). Writes out/uniaxial/study-SIZE/ (the runs, post.py's CSV
#   and PNG files); a results page takes what it shows from there into a folder of its own
#   under docs/results/uniaxial/, with the code revision. With CAPBRIDGE_LOCK=FILE every run
#   holds `flock FILE` (one heavy run at a time on a machine shared by several jobs); a run is
#   skipped when its end.dump exists already (delete the run directory to redo it).
#   -seed N: every run gets -var seed N, another packing (without it each deck's own seed:
#   LAMMPS 481903, LIGGGHTS 86028121; LIGGGHTS wants a prime above 10000 that none of its
#   other seeds uses, e.g. 86028157); SIZE becomes SIZE-seedN in the directory and file names.
set -euo pipefail
top=$(cd "$(dirname "$0")/../.." && pwd)
usage() { sed -n '2,15p' "$0" | sed 's/^# \{0,1\}//'; }
seed=()
while [ $# -gt 0 ]; do
  case $1 in
    -seed)
      case ${2:-} in
        ''|*[!0-9]*) echo "study.sh: -seed needs a whole number, not '${2:-}'" >&2; usage >&2; exit 2 ;;
      esac
      seed=(-var seed "$2"); shift 2 ;;
    -h|--help) usage; exit 0 ;;
    -*) echo "study.sh: unknown option '$1' (allowed: -seed N; the size and the engines are plain words)" >&2; usage >&2; exit 2 ;;
    *) break ;;
  esac
done
size=${1:-smoke}
shift || true
engines=("$@")
[ ${#engines[@]} -gt 0 ] || engines=(lammps liggghts)
case $size in smoke|default|paper) ;; *) echo "study.sh: size must be smoke, default or paper, not '$size'" >&2; usage >&2; exit 2 ;; esac
tag=$size                             # the size, and the seed when one is given
[ ${#seed[@]} -eq 0 ] || tag=$size-seed${seed[2]}
out=$top/out/uniaxial/study-$tag
mkdir -p "$out"
runs=()
one() {  # one ENGINE NAME -var ... : runs a case unless it finished before
  local engine=$1 name=$2; shift 2
  local dir=$out/$engine-$name
  runs+=("$dir")
  if [ -f "$dir/end.dump" ]; then return; fi
  echo "study.sh: $engine $name" >&2
  local lock=()
  [ -n "${CAPBRIDGE_LOCK:-}" ] && lock=(flock "$CAPBRIDGE_LOCK")
  "${lock[@]}" "$top/scripts/scene.sh" "$engine" uniaxial -np 2 -size "$size" -out "$dir" "${seed[@]+"${seed[@]}"}" "$@" >"$dir.screen" 2>&1 \
    || { echo "study.sh: $engine $name failed, see $dir.screen" >&2; exit 1; }
}
for engine in "${engines[@]}"; do
  case $engine in
    lammps) protocols=(protocol1 protocol2 protocol3) half=protocol2 ;;
    liggghts) protocols=(protocol1 protocol2 protocol3) half=protocol2 ;;
    *) echo "study.sh: unknown engine $engine" >&2; exit 2 ;;
  esac
  # first the curve sigma_rupt(w) of the first protocol, the half-bridges variant and dry,
  # then the other protocols
  for p in "${protocols[@]}"; do
    for w in 2 4 6; do one "$engine" "$p-w$w" -var protocol "$p" -var w "$w"; done
    if [ "$p" = "${protocols[0]}" ]; then
      for w in 2 4; do one "$engine" "$half-half-w$w" -var protocol "$half" -var w "$w" -var half yes; done
      one "$engine" dry -var dry yes
    fi
  done
done
/usr/bin/python3 "$top/inputs/uniaxial/post.py" "$out" "${runs[@]}" | tee "$out/strength.txt"
echo "study.sh: wrote $out"
