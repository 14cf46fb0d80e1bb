#!/usr/bin/env bash
# The LIGGGHTS model headers of lammps_pair/liggghts compile without a warning at -Wall
# -Wextra, as the rest of our C and C++ (CMakeLists.txt): LIGGGHTS's build uses its own flags
# (no -Wall), so this compiles its contact_models.cpp, where every contact model, ours
# included, is instantiated for pairs and walls, once more with them.  Warnings located in
# LIGGGHTS's own headers are not ours and are not counted.
#
# usage: model_warnings.sh LIGGGHTS_ENV
set -euo pipefail
[ $# -eq 1 ] || { echo "usage: model_warnings.sh LIGGGHTS_ENV" >&2; exit 2; }
# shellcheck disable=SC1090
. "$1"
ours=$(cd "$LIGGGHTS_MODELS_DIR" && ls ./*.h | sed 's|^\./||')
[ -n "$ours" ] || { echo "FAIL: no model headers in $LIGGGHTS_MODELS_DIR" >&2; exit 1; }
for h in $ours; do  # the copies LIGGGHTS compiles are this checkout's headers
  cmp -s "$LIGGGHTS_MODELS_DIR/$h" "$LIGGGHTS_SOURCE_DIR/$h" ||
    { echo "FAIL: $LIGGGHTS_SOURCE_DIR/$h is not $LIGGGHTS_MODELS_DIR/$h: run scripts/build_liggghts.sh" >&2; exit 1; }
done
log=$(mktemp)
trap 'rm -f "$log"' EXIT
mpicxx -std=c++11 -O2 -Wall -Wextra -Wno-literal-suffix -Wno-deprecated-declarations \
  -c -o /dev/null "$LIGGGHTS_SOURCE_DIR/contact_models.cpp" > "$log" 2>&1 ||
  { cat "$log"; echo "FAIL: contact_models.cpp does not compile" >&2; exit 1; }
pattern=$(printf '%s\n' "$ours" | sed 's/[.]/[.]/g; s|^|/|; s|$|:[0-9]+:[0-9]+: warning|' | paste -sd'|')
found=$(grep -E "$pattern" "$log" || true)
count=$(printf '%s' "$found" | grep -c warning || true)
echo "$(printf '%s\n' "$ours" | wc -l) model headers (in $LIGGGHTS_SOURCE_DIR); $(grep -c ': warning' "$log" || true) warnings in all, $count in ours"
if [ "$count" -ne 0 ]; then
  printf '%s\n' "$found"
  echo "FAIL: warnings in our model headers"
  exit 1
fi
echo "PASS"
