#!/usr/bin/env bash
# Build LAMMPS (Debian source package lammps=20250204+dfsg.1-2, i.e. upstream
# 4Feb2025) with the GRANULAR and PLUGIN packages, Open MPI and a shared
# library, into a cache outside the repository.  See scripts/README.md.
#
# Usage: scripts/build_lammps.sh [--force] [--print-env]
#   --force       rebuild even if the cache stamp is present
#   --print-env   only print the env file of a finished build (fails if none)
# Environment:
#   CAPBRIDGE_CACHE   cache root (default: $HOME/.cache/capbridge)
#   CAPBRIDGE_JOBS    parallel compile jobs (default: nproc)
#
# Result: $CAPBRIDGE_CACHE/lammps-20250204/lammps.env (shell KEY=VALUE lines,
# also printed on stdout at the end); source it to get LAMMPS_BINARY etc.
set -euo pipefail

ENGINE_TAG=lammps
SCRIPT_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
# shellcheck source=engine_common.sh
. "$SCRIPT_DIR/engine_common.sh"
eng_enable_err_trap

DEB_SUITE=trixie
DEB_PKG=lammps
DEB_VERSION=20250204+dfsg.1-2
ORIG_TARBALL=lammps_20250204+dfsg.1.orig.tar.xz
ORIG_SHA256=3671165bd52fad36734e0a9136c5bc5ecb225e03988f8c89aa13366a8b53b1c7
UPSTREAM_DIR=lammps-4Feb2025            # top directory inside the orig tarball
CACHE_DIR="$CAPBRIDGE_CACHE/lammps-20250204"
DL_DIR="$CAPBRIDGE_CACHE/downloads"
SRC_ROOT="$CACHE_DIR/source"             # the extracted tree lives here (headers for plugins)
SRC_DIR="$SRC_ROOT/$UPSTREAM_DIR"
BUILD_DIR="$CACHE_DIR/build"
PREFIX="$CACHE_DIR/prefix"
STAMP="$CACHE_DIR/.built-ok"
ENV_FILE="$CACHE_DIR/lammps.env"
LOG_FILE="$CACHE_DIR/build.log"

# The complete LAMMPS configuration.  Everything not listed is off: all PKG_*
# default to OFF in LAMMPS's CMake; the optional image/movie/compression
# helpers and OpenMP are switched off explicitly so the result does not depend
# on what else happens to be installed.  FFT settings only matter for KSPACE
# (off).  LAMMPS_EXCEPTIONS no longer exists in 4Feb2025 (C++ exceptions are
# always enabled).
CMAKE_FLAGS=(
  -G Ninja
  -DCMAKE_BUILD_TYPE=Release
  "-DCMAKE_CXX_FLAGS_RELEASE=-O2 -DNDEBUG"
  "-DCMAKE_INSTALL_PREFIX=$PREFIX"
  -DCMAKE_INSTALL_LIBDIR=lib
  -DLAMMPS_INSTALL_RPATH=on
  -DBUILD_SHARED_LIBS=on
  -DBUILD_MPI=on
  -DBUILD_OMP=off
  -DBUILD_TOOLS=off
  -DBUILD_LAMMPS_GUI=off
  -DBUILD_DOC=off
  -DENABLE_TESTING=off
  -DDOWNLOAD_POTENTIALS=off
  -DWITH_JPEG=off
  -DWITH_PNG=off
  -DWITH_GZIP=off
  -DWITH_FFMPEG=off
  -DPKG_GRANULAR=on
  -DPKG_PLUGIN=on
)
# A change of the configuration (or of the Debian version) invalidates the stamp.
CONFIG_KEY="$(printf '%s\n' "$DEB_VERSION" "${CMAKE_FLAGS[@]}" | sha256sum | cut -c1-16)"

force=0
print_only=0
for arg in "$@"; do
  case "$arg" in
    --force) force=1 ;;
    --print-env) print_only=1 ;;
    -h|--help) sed -n '2,16p' "$0"; exit 0 ;;
    *) die "unknown argument: $arg (try --help)" ;;
  esac
done

if [ "$print_only" -eq 1 ]; then
  if [ ! -f "$STAMP" ] || [ ! -f "$ENV_FILE" ]; then die "LAMMPS is not built yet; run $0"; fi
  cat "$ENV_FILE"
  exit 0
fi

if [ "$force" -eq 0 ] && [ -f "$STAMP" ] && [ "$(cat "$STAMP")" = "$CONFIG_KEY" ] \
   && [ -x "$PREFIX/bin/lmp" ] && [ -f "$ENV_FILE" ]; then
  log "LAMMPS $DEB_VERSION is cached in $CACHE_DIR (config $CONFIG_KEY); nothing to do"
  cat "$ENV_FILE"
  exit 0
fi

t_start=$(date +%s)
log "building LAMMPS $DEB_VERSION into $CACHE_DIR (config $CONFIG_KEY)"
mkdir -p "$CACHE_DIR" "$DL_DIR"
rm -f "$STAMP"

# --- 1. tools (Debian packages only) -------------------------------------
apt_install ca-certificates xz-utils cmake ninja-build g++ make \
  openmpi-bin libopenmpi-dev

# --- 2. source from Debian (deb-src only) --------------------------------
if [ ! -f "$DL_DIR/$ORIG_TARBALL" ]; then
  add_debsrc "$DEB_SUITE"
fi
fetch_debian_source "$DEB_PKG" "$DEB_VERSION" "$DL_DIR" "$ORIG_TARBALL"
log "verifying sha256 of $ORIG_TARBALL"
echo "$ORIG_SHA256  $DL_DIR/$ORIG_TARBALL" | sha256sum -c --quiet - \
  || die "checksum mismatch for $DL_DIR/$ORIG_TARBALL (delete it and rerun)"

if [ ! -f "$SRC_DIR/src/lammps.h" ] || [ ! -f "$SRC_ROOT/.extracted" ]; then
  log "extracting $ORIG_TARBALL into $SRC_ROOT"
  rm -rf "$SRC_ROOT"
  mkdir -p "$SRC_ROOT"
  tar -xJf "$DL_DIR/$ORIG_TARBALL" -C "$SRC_ROOT"
  [ -f "$SRC_DIR/src/lammps.h" ] || die "unexpected tarball layout: $SRC_DIR/src/lammps.h missing"
  touch "$SRC_ROOT/.extracted"
fi
# Debian's own patches (debian/patches in the .debian.tar.xz) only concern
# potential paths and documentation, so they are not applied.

# --- 3. configure, build, install ----------------------------------------
log "configuring (log: $LOG_FILE)"
: > "$LOG_FILE"
if [ -f "$BUILD_DIR/CMakeCache.txt" ] && ! grep -q "^CMAKE_GENERATOR:INTERNAL=Ninja$" "$BUILD_DIR/CMakeCache.txt"; then
  rm -rf "$BUILD_DIR"
fi
mkdir -p "$BUILD_DIR"
if ! cmake -S "$SRC_DIR/cmake" -B "$BUILD_DIR" "${CMAKE_FLAGS[@]}" >>"$LOG_FILE" 2>&1; then
  tail -n 40 "$LOG_FILE" >&2
  die "cmake configure failed; full log: $LOG_FILE"
fi
grep -E 'LAMMPS Version|Build type|Enabled packages|C\+\+ (Compiler|Standard|Flags)|Defines|MPI v|Using ' "$LOG_FILE" | sed 's/^-- //; s/^ */    /' >&2 || true

log "compiling with $CAPBRIDGE_JOBS jobs (a fresh build takes ~5 min on 2 cores)"
if ! cmake --build "$BUILD_DIR" --parallel "$CAPBRIDGE_JOBS" >>"$LOG_FILE" 2>&1; then
  grep -nE 'error|Error' "$LOG_FILE" | head -n 30 >&2 || true
  tail -n 20 "$LOG_FILE" >&2
  die "compilation failed; full log: $LOG_FILE"
fi
log "installing into $PREFIX"
rm -rf "$PREFIX"
cmake --install "$BUILD_DIR" >>"$LOG_FILE" 2>&1 || die "cmake --install failed; see $LOG_FILE"

# --- 4. smoke test ---------------------------------------------------------
LMP="$PREFIX/bin/lmp"
[ -x "$LMP" ] || die "$LMP was not installed"
[ -e "$PREFIX/lib/liblammps.so" ] || die "$PREFIX/lib/liblammps.so was not installed"
help_out="$("$LMP" -h 2>&1)" || die "$LMP -h failed: $help_out"
pkgs="$(sed -n '/^Installed packages:/,/^List of individual style/p' <<<"$help_out")"
for want in GRANULAR PLUGIN; do
  grep -qw "$want" <<<"$pkgs" || die "package $want missing from $LMP"
done
grep -q 'MPI v' <<<"$help_out" || log "warning: could not confirm MPI library in 'lmp -h'"

# --- 5. env file -----------------------------------------------------------
lmp_defines="$(grep -oE 'LAMMPS_(SMALLBIG|BIGBIG|SMALLSMALL)' "$BUILD_DIR/CMakeCache.txt" | head -n1 || true)"
[ -n "$lmp_defines" ] || lmp_defines=LAMMPS_SMALLBIG
tmp_env="$ENV_FILE.tmp"
cat > "$tmp_env" <<EOF
# Written by capbridge scripts/build_lammps.sh; source this file.
LAMMPS_VERSION=20250204
LAMMPS_DEB_VERSION=$DEB_VERSION
LAMMPS_PREFIX=$PREFIX
LAMMPS_BINARY=$PREFIX/bin/lmp
LAMMPS_LIBRARY=$PREFIX/lib/liblammps.so
LAMMPS_SOURCE_DIR=$SRC_DIR/src
LAMMPS_HEADER_DIR=$SRC_DIR/src
LAMMPS_BUILD_DIR=$BUILD_DIR
LAMMPS_CMAKE_DIR=$PREFIX/lib/cmake/LAMMPS
LAMMPS_PLUGIN_CMAKE_MODULE_DIR=$SRC_DIR/examples/plugins
LAMMPS_CXX_DEFINES="-D$lmp_defines"
LAMMPS_MPIRUN="mpirun --allow-run-as-root --oversubscribe"
EOF
mv "$tmp_env" "$ENV_FILE"
echo "$CONFIG_KEY" > "$STAMP"

t_end=$(date +%s)
log "LAMMPS built and installed in $(( t_end - t_start )) s; env file: $ENV_FILE"
cat "$ENV_FILE"
