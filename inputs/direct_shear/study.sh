#!/usr/bin/env bash
# The direct shear study of Richefeu 2007 section 3.2 (Figs. 5-7): runs the matrix through
# scripts/scene.sh, then post.py; copies the CSV and PNG into docs/results/direct_shear/ (smoke)
# or docs/results/direct_shear/SIZE/.
#
# Usage: inputs/direct_shear/study.sh [-size smoke|default|paper] [-np N] [-engines "lammps liggghts"]
#                                     [-sigmas "200 500 800"] [-ws "0 0.1 0.5 1 2"] [-protocols "1 2"]
#                                     [-seeds "0 1 2"] [-nohalf] [-nocopy]
#   the full matrix at default size (the command the results page refers to):
#     CAPBRIDGE_SKIP_CONFIGURE=1 inputs/direct_shear/study.sh -size default
#   LAMMPS: Protocols 1 and 2 for every wet w (-protocols: a subset); LIGGGHTS: protocol2 (it has no Protocol 1);
#   dry runs once per engine and sigma; the half-bonds variant (Fig. 7): LAMMPS, Protocol 2,
#   w = 1 %, the middle sigma, next to its all-bonds run.
#   -seeds: every run once per packing (default "0"); seed 0 is the deck's own seed and the run
#   name above, seed k adds -seedk to it and gives the deck seed 5871 + k (LAMMPS) or the k-th
#   prime after its 15485863 that the deck does not use itself (LIGGGHTS takes distinct primes), k = 0..5.
# Outputs: out/direct_shear/study-SIZE/<engine>-p<protocol>-<bonds>-s<sigma>-w<w>/ (one run each),
#   out/direct_shear/study-SIZE/post/ (post.py), copied as above (-nocopy: not).
# Environment: CAPBRIDGE_LOCK=FILE runs every engine under `flock FILE` (one heavy run at a time on a
#   shared machine); CAPBRIDGE_SKIP_CONFIGURE, CAPBRIDGE_PLUGIN are passed on to scripts/scene.sh.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/../.." && pwd)
size=default np=2 engines="lammps liggghts" sigmas="200 500 800" ws="0 0.1 0.5 1 2" lammps_protocols="1 2" half=1 copy=1
seeds=0
liggghts_primes=(15485863 15485917 15485927 15485933 15485941 15485959)  # not 15485867: the deck's template seed (LIGGGHTS wants all seeds distinct)
usage() { sed -n '2,20p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
while [ $# -gt 0 ]; do
  case $1 in
    -size|-np|-engines|-sigmas|-ws|-protocols|-seeds)
      [ $# -ge 2 ] || { echo "study.sh: $1 needs a value" >&2; usage; } ;;
  esac
  case $1 in
    -size) size=$2; shift 2 ;;
    -np) np=$2; shift 2 ;;
    -engines) engines=$2; shift 2 ;;
    -sigmas) sigmas=$2; shift 2 ;;
    -ws) ws=$2; shift 2 ;;
    -protocols) lammps_protocols=$2; shift 2 ;;
    -seeds) seeds=$2; shift 2 ;;
    -nohalf) half=0; shift ;;
    -nocopy) copy=0; shift ;;
    -h|--help) usage ;;
    *) echo "study.sh: unknown option '$1'" >&2; usage ;;
  esac
done
# checked here, before any run or directory (scene.sh checks them again, one run at a time)
case $size in smoke|default|paper) ;; *) echo "study.sh: -size must be smoke, default or paper, not '$size'" >&2; exit 2 ;; esac
case $np in ''|*[!0-9]*|0) echo "study.sh: -np must be a positive integer, not '$np'" >&2; exit 2 ;; esac
for engine in $engines; do
  case $engine in lammps|liggghts) ;; *) echo "study.sh: unknown engine '$engine' (allowed: lammps, liggghts)" >&2; exit 2 ;; esac
done
for p in $lammps_protocols; do
  case $p in 1|2) ;; *) echo "study.sh: -protocols takes 1, 2, not '$p'" >&2; exit 2 ;; esac
done
for k in $seeds; do
  case $k in [0-5]) ;; *) echo "study.sh: -seeds takes packings 0..5, not '$k'" >&2; exit 2 ;; esac
done
# the smoke-size results live in docs/results/direct_shear/, the others in a directory of
# their size: a default-size study never overwrites the smoke files
dest="$top/docs/results/direct_shear"
[ "$size" = smoke ] || dest="$dest/$size"
study="$top/out/direct_shear/study-$size"
mkdir -p "$study"
# ranks waiting in MPI give the core to the other rank (the machine may be shared)
export OMPI_MCA_mpi_yield_when_idle=${OMPI_MCA_mpi_yield_when_idle:-1}

one() {  # one ENGINE NAME -var ...: one run per seed unless its shear.txt is complete
  local engine=$1 name=$2 k
  shift 2
  for k in $seeds; do
    if [ "$k" = 0 ]; then
      one_seed "$engine" "$name" "$@"
    elif [ "$engine" = lammps ]; then
      one_seed "$engine" "$name-seed$k" "$@" -var seed $((5871 + k))
    else
      one_seed "$engine" "$name-seed$k" "$@" -var seed "${liggghts_primes[$k]}"
    fi
  done
}

one_seed() {  # one_seed ENGINE NAME -var ...: one run unless its shear.txt is complete
  local engine=$1 name=$2
  shift 2
  local out="$study/$name"
  if [ -f "$out/shear.txt" ] && grep -q "direct_shear: done" "$out"/log.* 2>/dev/null; then
    echo "study: $name done before, kept"
    return
  fi
  echo "study: $name ($(date -u +%H:%M:%S))"
  local lock=()
  [ -n "${CAPBRIDGE_LOCK:-}" ] && lock=(flock "$CAPBRIDGE_LOCK")
  local t0=$SECONDS
  "${lock[@]}" "$top/scripts/scene.sh" "$engine" direct_shear -np "$np" -size "$size" -out "$out" "$@" \
    > "$out.screen" 2>&1 || { echo "study: $name failed, see $out.screen" >&2; exit 1; }
  echo "study: $name took $((SECONDS - t0)) s"
}

mid=$(echo "$sigmas" | awk '{print $(int((NF + 1) / 2))}')
for engine in $engines; do
  if [ "$engine" = lammps ]; then protocols=$lammps_protocols; else protocols="protocol2"; fi
  for sigma in $sigmas; do
    for w in $ws; do
      if [ "$w" = 0 ]; then
        one "$engine" "$engine-dry-all-s$sigma-w0" -var sigma "$sigma" -var w 0
        continue
      fi
      for p in $protocols; do
        if [ "$engine" = lammps ]; then pvar=(-var protocol "$p"); else pvar=(-var liquid "$p"); fi
        one "$engine" "$engine-p$p-all-s$sigma-w$w" -var sigma "$sigma" -var w "$w" "${pvar[@]}"
      done
    done
  done
  if [ "$engine" = lammps ] && [ "$half" = 1 ]; then
    one lammps "lammps-p2-all-s$mid-w1" -var sigma "$mid" -var w 1 -var protocol 2
    one lammps "lammps-p2-half-s$mid-w1" -var sigma "$mid" -var w 1 -var protocol 2 -var bonds half
  fi
done

mkdir -p "$study/post"
/usr/bin/python3 "$here/post.py" "$study" --out "$study/post" | tee "$study/post/summary.txt"
if [ "$copy" = 1 ]; then
  mkdir -p "$dest"
  cp "$study"/post/*.csv "$study"/post/*.png "$study/post/summary.txt" "$dest/"
  echo "study: copied to $dest"
fi
