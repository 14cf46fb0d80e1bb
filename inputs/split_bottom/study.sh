#!/usr/bin/env bash
# The split-bottom study (Gladkyy 2014 §4.1, Figs. 6-8): dry, then every law at both bridge
# volumes, in one or both engines; then post.py over all runs, and the CSV + PNG copied to
# docs/results/split_bottom/ (smoke) or docs/results/split_bottom/SIZE/ (with -publish).
#
# Usage: inputs/split_bottom/study.sh [-size smoke|default|large|paper] [-engines "lammps liggghts"]
#                                     [-laws "weigert willett ..."] [-volumes "13.6 74.2"]
#                                     [-seeds "0 1 2"] [-dashpot approach|both] [-np N] [-publish]
#   defaults: -size default, both engines, Gladkyy's four laws (weigert willett
#   willett/reduced rabinovich) and the other four of capbridge (richefeu
#   rabinovich/uncorrected soulie table), volumes 13.6 and 74.2 nl, seed 0, -np 2.
#   -seeds: every run once per seed (params.in: another packing of the same cell); seed 0
#   is the run named ENGINE-LAW-VOLUME, seed N > 0 adds -seedN to the name.  -volumes ""
#   runs dry only.  The contact is Gladkyy's (§2: dashpot both ways, never attractive;
#   in.lammps's dashpot repulsive, in.liggghts's limitForce on); -dashpot approach|both:
#   LAMMPS's contact with Richefeu's dashpot (approach only) or one that may pull, run names
#   get -approach or -both; LIGGGHTS keeps Gladkyy's.
#   The full matrix at default size (the paper's period 100 s since 2026-12-07) is 2 engines x 17
#   runs x ~2 min (LAMMPS; LIGGGHTS see docs/results/split_bottom/default-rate/) on 2 idle cores.
# With CAPBRIDGE_LOCK=FILE every run holds `flock FILE` (one heavy run at a time on a machine
# shared by several jobs).
# Runs go to out/split_bottom/study-SIZE/ENGINE-LAW-VOLUME/ (an existing run with a snapshot
# and a finished log is kept: delete it to run again); post.py writes out/split_bottom/study-SIZE/post/.
set -euo pipefail
top=$(cd "$(dirname "$0")/../.." && pwd)
size=default engines="lammps liggghts" np=2 publish=0 seeds=0 dashpot=repulsive
laws="weigert willett willett/reduced rabinovich richefeu rabinovich/uncorrected soulie table"
volumes="13.6 74.2"
while [ $# -gt 0 ]; do
  case $1 in
    -size) size=$2; shift 2 ;;
    -engines) engines=$2; shift 2 ;;
    -laws) laws=$2; shift 2 ;;
    -volumes) volumes=$2; shift 2 ;;
    -seeds) seeds=$2; shift 2 ;;
    -dashpot) dashpot=$2; shift 2 ;;
    -np) np=$2; shift 2 ;;
    -publish) publish=1; shift ;;
    *) sed -n '6,20p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2 ;;
  esac
done
case $dashpot in repulsive|approach|both) ;; *) echo "study.sh: -dashpot takes repulsive (the default), approach or both, not '$dashpot'" >&2; exit 2 ;; esac
case $size in smoke|default|large|paper) ;; *) echo "study.sh: -size must be smoke, default, large or paper, not '$size'" >&2; exit 2 ;; esac
for engine in $engines; do
  case $engine in lammps|liggghts) ;; *) echo "study.sh: unknown engine '$engine' (allowed: lammps, liggghts)" >&2; exit 2 ;; esac
done
for seed in $seeds; do
  case $seed in ''|*[!0-9]*) echo "study.sh: -seeds takes whole numbers >= 0, not '$seed'" >&2; exit 2 ;; esac
done
lock=()
[ -n "${CAPBRIDGE_LOCK:-}" ] && lock=(flock "$CAPBRIDGE_LOCK")
study=$top/out/split_bottom/study-$size
mkdir -p "$study"
runs=()
one() {  # engine law volume seed
  local name="$1-${2//\//_}-$3"
  [ "$3" != 0 ] || name="$1-dry"
  [ "$4" = 0 ] || name="$name-seed$4"
  [ "$dashpot" = repulsive ] || [ "$1" != lammps ] || name="$name-$dashpot"
  local out="$study/$name"
  runs+=("$out")
  if grep -qs "^SPLIT_BOTTOM_DONE" "$out"/log.*; then
    echo "study: $name done before, kept"
    return
  fi
  echo "study: $name ($(date -u +%H:%M:%S))"
  local t0=$SECONDS
  # the dashpot choice is LAMMPS's (LIGGGHTS's hooke damps both ways)
  local extra=()
  [ "$1" = lammps ] && extra=(-var dashpot "$dashpot")
  CAPBRIDGE_SKIP_CONFIGURE=${CAPBRIDGE_SKIP_CONFIGURE:-1} "${lock[@]}" \
    "$top/scripts/scene.sh" "$1" split_bottom -np "$np" -size "$size" -out "$out" \
    -var law "$2" -var volume "$3" -var seed "$4" "${extra[@]+"${extra[@]}"}" \
    > "$study/$name.out" 2>&1 ||
    { echo "study: $name failed: $(grep -m1 -E 'ERROR|scene.sh:|split_bottom:' "$study/$name.out" ||
                                     tail -n 1 "$study/$name.out")" >&2; exit 1; }
  echo "study: $name took $((SECONDS - t0)) s"
}
for engine in $engines; do
  for seed in $seeds; do
    one "$engine" willett 0 "$seed"
    for volume in $volumes; do
      for law in $laws; do
        one "$engine" "$law" "$volume" "$seed"
      done
    done
  done
done
/usr/bin/python3 "$top/inputs/split_bottom/post.py" "${runs[@]}" --out "$study/post"
if [ "$publish" = 1 ]; then
  dest=$top/docs/results/split_bottom   # the smoke figures; other sizes in a subdirectory
  [ "$size" = smoke ] || dest=$dest/$size
  mkdir -p "$dest"
  cp "$study/post/summary.csv" "$study/post/band_shift.csv" "$study/post/"*.png "$dest/"
  cp "$study/post/"*_band.csv "$dest/"
  echo "study: copied summary.csv, band_shift.csv, *_band.csv and the plots to $dest"
fi
