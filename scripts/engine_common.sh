# shellcheck shell=bash
# Helpers shared by scripts/build_lammps.sh and scripts/build_liggghts.sh.
# Source this file; do not execute it.
#
# Policy (see scripts/README.md):
#   * Only Debian packages (apt) are installed.
#   * Engine sources come from Debian *source* packages via `apt-get source`,
#     using a deb-src-only entry in its own sources.list.d file.  No binary
#     repository of another release is ever added, and an apt preferences file
#     pins such releases to -1 as a second line of defence.
#   * Everything built lives in a cache outside the repository:
#     ${CAPBRIDGE_CACHE:-$HOME/.cache/capbridge}/<engine>-<version>/

CAPBRIDGE_CACHE="${CAPBRIDGE_CACHE:-${HOME:-/root}/.cache/capbridge}"
# Parallel build jobs; the reference machine has 2 cores shared with other work.
CAPBRIDGE_JOBS="${CAPBRIDGE_JOBS:-$(nproc 2>/dev/null || echo 2)}"

_eng_tag="${ENGINE_TAG:-engine}"

log()  { printf '[%s %s] %s\n' "$_eng_tag" "$(date +%H:%M:%S)" "$*" >&2; }
die()  { printf '[%s] ERROR: %s\n' "$_eng_tag" "$*" >&2; exit 1; }

# Report the failing command and line on any error (set -e exit).
_eng_err_trap() {
  local rc=$? line=$1 cmd=$2
  printf '[%s] ERROR: command failed (exit %s) at line %s: %s\n' \
    "$_eng_tag" "$rc" "$line" "$cmd" >&2
  exit "$rc"
}
eng_enable_err_trap() { set -E; trap '_eng_err_trap "$LINENO" "$BASH_COMMAND"' ERR; }

need_root() {
  if [ "$(id -u)" -ne 0 ]; then
    die "must run as root (installs Debian packages and an apt deb-src entry); run with sudo"
  fi
}

# apt-get update at most once per script run.
_eng_apt_updated=0
apt_update_once() {
  if [ "$_eng_apt_updated" -eq 0 ]; then
    log "apt-get update"
    DEBIAN_FRONTEND=noninteractive apt-get update -qq >&2 \
      || die "apt-get update failed"
    _eng_apt_updated=1
  fi
}

# apt_install PKG... : install Debian packages that are not installed yet.
apt_install() {
  local missing=() p
  for p in "$@"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
      missing+=("$p")
    fi
  done
  if [ "${#missing[@]}" -eq 0 ]; then
    return 0
  fi
  need_root
  apt_update_once
  log "apt-get install ${missing[*]}"
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
    "${missing[@]}" >&2 || die "apt-get install ${missing[*]} failed"
}

# add_debsrc SUITE : add a deb-src-only entry for Debian SUITE (own file) and,
# unless SUITE is the release this system runs, pin that suite's binaries to
# -1 so nothing can ever be installed from it.
add_debsrc() {
  local suite=$1
  local own_suite
  own_suite="$( (. /etc/os-release && echo "${VERSION_CODENAME:-}") 2>/dev/null || true)"
  local list="/etc/apt/sources.list.d/capbridge-${suite}-src.sources"
  local pref="/etc/apt/preferences.d/capbridge-${suite}-nobinaries"
  local keyring=/usr/share/keyrings/debian-archive-keyring.gpg
  local want
  want="# Added by capbridge scripts/engine_common.sh: SOURCE packages only.
# Do not add 'deb' here: binaries of ${suite} must never reach this system.
Types: deb-src
URIs: http://deb.debian.org/debian
Suites: ${suite}
Components: main
Signed-By: ${keyring}
"
  local pwant
  pwant="# Added by capbridge scripts/engine_common.sh: never install binaries
# from ${suite}; only its deb-src entry is configured.
Package: *
Pin: release n=${suite}
Pin-Priority: -1
"
  if [ "$suite" = "$own_suite" ]; then
    # Binaries of the running release are the system itself: no pin.
    pwant=""
  fi
  local have_pref=""
  [ -f "$pref" ] && have_pref="$(cat "$pref")"
  if [ ! -f "$list" ] || [ "$(cat "$list")" != "$(printf '%s' "$want")" ] \
     || [ "$have_pref" != "$(printf '%s' "$pwant")" ]; then
    need_root
    printf '%s' "$want" > "$list"
    if [ -n "$pwant" ]; then
      log "adding deb-src entry for ${suite}: $list (+ pin -1 for its binaries in $pref)"
      printf '%s' "$pwant" > "$pref"
    else
      log "adding deb-src entry for ${suite} (the running release): $list"
      rm -f "$pref"
    fi
    _eng_apt_updated=0
  fi
  apt_update_once
}

# fetch_debian_source PKG VERSION DESTDIR ORIG_GLOB
# Downloads the source package tarballs with `apt-get source --download-only`
# into DESTDIR.  The .dsc (or the Debian diff) may not be served by the mirror,
# so apt-get's exit status is ignored; success means a file matching ORIG_GLOB
# exists afterwards.
fetch_debian_source() {
  local pkg=$1 ver=$2 dest=$3 glob=$4
  mkdir -p "$dest"
  # shellcheck disable=SC2086
  if compgen -G "$dest/$glob" >/dev/null; then
    log "source tarball already downloaded: $(cd "$dest" && ls $glob)"
    return 0
  fi
  local spec=$pkg
  [ -n "$ver" ] && spec="$pkg=$ver"
  log "apt-get source --download-only $spec (into $dest)"
  # apt-get source downloads into the current directory; use a scratch
  # directory that apt's sandbox user (_apt) may write to, then move.
  local tmp
  tmp="$(mktemp -d "${TMPDIR:-/tmp}/capbridge-src.XXXXXX")"
  chmod 0755 "$tmp"
  if id _apt >/dev/null 2>&1; then chown _apt "$tmp" 2>/dev/null || true; fi
  ( cd "$tmp" && apt-get source --download-only -q "$spec" ) >&2 \
    || log "apt-get source exited non-zero (expected here: the .dsc or Debian diff is not served); checking the tarballs"
  # shellcheck disable=SC2086
  if compgen -G "$tmp/$glob" >/dev/null; then
    find "$tmp" -maxdepth 1 -type f -name '*.tar.*' -exec mv -f {} "$dest/" \;
  fi
  rm -rf "$tmp"
  compgen -G "$dest/$glob" >/dev/null \
    || die "apt-get source did not bring $glob for $spec (is the deb-src entry there and 'apt-get update' done?)"
  # shellcheck disable=SC2086
  log "downloaded: $(cd "$dest" && ls $glob)"
}

# sha256 of the concatenated names+contents of the given files (stable order).
hash_files() {
  local f
  for f in "$@"; do
    printf '%s\n' "$(basename "$f")"
    cat "$f"
  done | sha256sum | cut -c1-16
}
