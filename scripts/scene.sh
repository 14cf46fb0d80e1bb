#!/usr/bin/env bash
# Runs one scene deck in LAMMPS or LIGGGHTS under MPI.
#
# Usage: scripts/scene.sh ENGINE SCENE [-np N] [-size smoke|default|paper] [-out DIR]
#                         [-var NAME VALUE ...]
#   ENGINE  lammps or liggghts
#   SCENE   a directory of inputs/ (direct_shear, uniaxial, split_bottom)
#   -np     MPI ranks (default 2)
#   -size   the deck's size (default: default); split_bottom also has large
#   -out    output directory, created if needed (default out/SCENE/ENGINE-SIZE)
#   -var    passed on to the deck (any number); NAME must be one of the deck's own
#           variables (its `variable NAME index` lines and those of the scene's shared
#           files), so that a misspelt or the other engine's name is refused, not ignored,
#           and a variable whose default is a number takes a number
# The deck is inputs/SCENE/in.ENGINE. It runs in the output directory and gets the variables
# size, inputs (the scene directory), and for LAMMPS plugin (the capbridge plugin).
# Set CAPBRIDGE_SKIP_CONFIGURE=1 when build/ is known to be current (the tests do).
# CAPBRIDGE_DECK=FILE runs FILE in place of the scene's deck, with the scene's variables and
# files (scripts/same_trajectory.py -fixed-bins gives it a copy with two commands added).
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
usage() { sed -n '4,17p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
[ $# -ge 2 ] || usage
engine=$1 scene=$2
shift 2
case $engine in lammps|liggghts) ;; *) echo "scene.sh: unknown engine '$engine' (allowed: lammps, liggghts)" >&2; exit 2 ;; esac
deck=${CAPBRIDGE_DECK:-$top/inputs/$scene/in.$engine}
[ -f "$deck" ] || { echo "scene.sh: no deck $deck (scenes: $(ls "$top/inputs" | tr '\n' ' '))" >&2; exit 2; }
np=2 size=default out="" vars=()
need() {  # need OPTION COUNT ARGS...: the option has its values
  [ $(($# - 4)) -ge "$2" ] || { echo "scene.sh: $1 needs $3" >&2; exit 2; }
}
while [ $# -gt 0 ]; do
  case $1 in
    -np) need -np 1 "a number" "$@"; np=$2; shift 2 ;;
    -size) need -size 1 "a size: smoke, default, paper" "$@"; size=$2; shift 2 ;;
    -out) need -out 1 "a directory" "$@"; out=$2; shift 2 ;;
    -var) need -var 2 "NAME VALUE" "$@"; vars+=(-var "$2" "$3"); shift 3 ;;
    *) echo "scene.sh: unknown option '$1'" >&2; usage ;;
  esac
done
# the variables the deck takes: the index variables of the deck, of the scene's shared
# .in files and of its files for this engine (LAMMPS ignores a -var the deck never reads)
files=("$deck")
for f in "$top/inputs/$scene"/*.in "$top/inputs/$scene"/*."$engine"; do [ -f "$f" ] && files+=("$f"); done
known=$(grep -ho 'variable[[:space:]]\+[A-Za-z_][A-Za-z0-9_]*[[:space:]]\+index' "${files[@]}" |
  awk '{print $2}' | sort -u | tr '\n' ' ')
number='^[+-]?([0-9]+[.]?[0-9]*|[.][0-9]+)([eE][+-]?[0-9]+)?$'
set -- "${vars[@]+"${vars[@]}"}"
while [ $# -gt 0 ]; do    # -var NAME VALUE triples
  name=$2 value=$3
  shift 3
  case " $known size inputs plugin " in
    *" $name "*) ;;
    *) echo "scene.sh: inputs/$scene/in.$engine has no variable '$name' (it takes: $known)" >&2
       exit 2 ;;
  esac
  # a variable whose default is a number takes a number (the engines would stop later with
  # an error about an if or a formula that does not name the variable)
  default=$( { grep -h "variable[[:space:]]\+$name[[:space:]]\+index" "${files[@]}" || true; } |
    awk 'NR == 1 {print $4}')
  if printf '%s' "$default" | grep -Eq "$number" && ! printf '%s' "$value" | grep -Eq "$number"; then
    echo "scene.sh: -var $name '$value' is not a number (the deck's default: $default)" >&2
    exit 2
  fi
done
# every scene has smoke, default and paper; a scene may add sizes of its own (size_NAME.in)
extra=""
for f in "$top/inputs/$scene"/size_*.in; do
  name=${f##*/size_}; name=${name%.in}
  case $name in smoke|default|paper|'*') ;; *) extra="$extra, $name" ;; esac
done
case $size in
  smoke|default|paper) ;;
  *) [ -f "$top/inputs/$scene/size_$size.in" ] ||
       { echo "scene.sh: unknown size '$size' (allowed: smoke, default, paper$extra)" >&2; exit 2; } ;;
esac
case $np in ''|*[!0-9]*|0) echo "scene.sh: -np must be a positive integer, not '$np'" >&2; exit 2 ;; esac
[ -n "$out" ] || out="$top/out/$scene/$engine-$size"
[ "${CAPBRIDGE_SKIP_CONFIGURE:-0}" = 1 ] || "$top/scripts/configure.sh"
cache=${CAPBRIDGE_CACHE:-$HOME/.cache/capbridge}
if [ "$engine" = lammps ]; then
  envfile="$cache/lammps-20250204/lammps.env"
else
  envfile="$cache/liggghts-3.8.0/liggghts.env"
fi
set -a
# shellcheck disable=SC1090
. "$envfile"
set +a
# Open MPI inside containers: allow root, do not bind oversubscribed ranks
export OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_hwloc_base_binding_policy=none
mkdir -p "$out"
cd "$out"
if [ "$engine" = lammps ]; then
  plugin=${CAPBRIDGE_PLUGIN:-$top/build/lammps_pair/lammps/capbridgeplugin.so}
  [ -f "$plugin" ] || { echo "scene.sh: no plugin $plugin (run scripts/configure.sh)" >&2; exit 2; }
  # shellcheck disable=SC2086 # LAMMPS_MPIRUN is a command with options
  exec ${LAMMPS_MPIRUN:-mpirun} -np "$np" "$LAMMPS_BINARY" -in "$deck" -log log.lammps \
    -nocite -var size "$size" -var inputs "$top/inputs/$scene" -var plugin "$plugin" \
    "${vars[@]+"${vars[@]}"}" </dev/null
else
  # shellcheck disable=SC2086
  exec ${LIGGGHTS_MPIRUN:-mpirun} -np "$np" "$LIGGGHTS_BINARY" -in "$deck" -log log.liggghts \
    -var size "$size" -var inputs "$top/inputs/$scene" "${vars[@]+"${vars[@]}"}" </dev/null
fi
