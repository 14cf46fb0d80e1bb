#!/bin/sh
# Install.sh — build pair style gran/capillary, fix capillary/liquid and fix capillary/wall
# into LAMMPS the classic way (compiled into the LAMMPS library and binary, no plugin), for
# LAMMPS's CMake build.
#
#   lammps_pair/lammps/Install.sh LAMMPS_DIR          copy the files in
#   lammps_pair/lammps/Install.sh LAMMPS_DIR --remove take them out again
#
# LAMMPS_DIR is the top of a LAMMPS source tree (with src/ and cmake/).  Copied:
#   src/pair_gran_capillary.{h,cpp}, src/fix_capillary_{liquid,wall}.{h,cpp},  the binding
#   src/capillary_*.{h,cpp}                                        (the list: $binding below)
#   src/CAPBRIDGE_CORE/   the capbridge core: capbridge.h, the C99 sources (src_c/*.c) and
#                         their internal headers, and capbridge.cmake
# LAMMPS's CMake build compiles the .cpp files of src/ (and finds the styles in the
# headers by itself) but no C file; capbridge.cmake, given to CMake as the include file
# of the project, compiles the core as C99 and adds its objects to the lammps target:
#
#   cmake -S LAMMPS_DIR/cmake -B build -D PKG_GRANULAR=on \
#         -D CMAKE_PROJECT_lammps_INCLUDE=LAMMPS_DIR/src/CAPBRIDGE_CORE/capbridge.cmake
#   cmake --build build
#
# The GRANULAR package is not required by the binding but is what granular decks use
# (fix wall/gran, fix pour).  The PLUGIN package is not needed for this way.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
core=$(cd "$here/../../src_c" && pwd)
lammps=${1:?"usage: $0 LAMMPS_DIR [--remove]"}
[ -f "$lammps/src/pair.h" ] && [ -d "$lammps/cmake" ] ||
    { echo "$0: '$lammps' is not a LAMMPS source tree (src/pair.h, cmake/)" >&2; exit 2; }
binding="pair_gran_capillary.h pair_gran_capillary.cpp capillary_coeff.cpp capillary_history.cpp
         capillary_checks.cpp capillary_bridges.h capillary_bridges.cpp capillary_liquid_mode.h
         fix_capillary_liquid.h fix_capillary_liquid.cpp capillary_protocols.cpp
         fix_capillary_wall.h fix_capillary_wall.cpp"

if [ "${2:-}" = "--remove" ]; then
    for f in $binding; do rm -f "$lammps/src/$f"; done
    rm -rf "$lammps/src/CAPBRIDGE_CORE"
    echo "removed gran/capillary, capillary/liquid and capillary/wall from $lammps/src"
    exit 0
fi

for f in $binding; do cp "$here/$f" "$lammps/src/$f"; done
rm -rf "$lammps/src/CAPBRIDGE_CORE"
mkdir -p "$lammps/src/CAPBRIDGE_CORE"
cp "$core"/*.c "$core"/*.h "$lammps/src/CAPBRIDGE_CORE/"
cat >"$lammps/src/CAPBRIDGE_CORE/capbridge.cmake" <<'CMAKE'
# capbridge core for LAMMPS's CMake build (written by capbridge's Install.sh):
#   -D CMAKE_PROJECT_lammps_INCLUDE=<this file>
# Included right after project(lammps); the lammps target does not exist yet, so the
# core's objects are attached at the end of the directory (cmake_language DEFER).
cmake_minimum_required(VERSION 3.19)
enable_language(C)
set(CAPBRIDGE_CORE_DIR "${CMAKE_CURRENT_LIST_DIR}")
function(capbridge_attach_core)
  file(GLOB sources CONFIGURE_DEPENDS "${CAPBRIDGE_CORE_DIR}/*.c")
  add_library(capbridge_core OBJECT ${sources})
  set_target_properties(capbridge_core PROPERTIES
    C_STANDARD 99 C_STANDARD_REQUIRED ON C_EXTENSIONS OFF POSITION_INDEPENDENT_CODE ON)
  target_include_directories(capbridge_core PRIVATE "${CAPBRIDGE_CORE_DIR}")
  target_sources(lammps PRIVATE $<TARGET_OBJECTS:capbridge_core>)
  target_include_directories(lammps PRIVATE "${CAPBRIDGE_CORE_DIR}")
  target_link_libraries(lammps PRIVATE m)
endfunction()
cmake_language(DEFER CALL capbridge_attach_core)
CMAKE
echo "installed gran/capillary, capillary/liquid and capillary/wall into $lammps/src; configure LAMMPS with"
echo "  -D CMAKE_PROJECT_lammps_INCLUDE=$lammps/src/CAPBRIDGE_CORE/capbridge.cmake"
