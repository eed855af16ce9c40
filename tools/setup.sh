#!/usr/bin/env bash
# Set up cellsph on Debian 12: system packages, a plugin-capable LAMMPS (cached outside the work
# tree), and the plugin itself. Idempotent: a second run takes seconds. Changes nothing outside
# the repository and the cache but the Debian packages it installs (/etc/apt is left as it is).
#
#   LAMMPS_PREFIX       use this installed LAMMPS (a `cmake --install` prefix, an HPC module)
#                       instead of building one; give LAMMPS_SOURCE_DIR too when the install lacks
#                       headers the plugin needs (29 Sep 2021 installs only some of them)
#   LAMMPS_SOURCE_DIR   use this LAMMPS tree (top level, holding src/ and cmake/) instead of the
#                       Debian source package
#   LAMMPS_BUILD_DIR    an existing CMake build of that tree to use as is (must have PKG_PLUGIN;
#                       29Sep2021 builds also need BUILD_SHARED_LIBS=on)
#   CELLSPH_CACHE       cache for the LAMMPS source and build (default ~/.cache/cellsph)
#   CELLSPH_BUILD       build folder of the plugin (default <repo>/build)
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cache=${CELLSPH_CACHE:-$HOME/.cache/cellsph}
build=${CELLSPH_BUILD:-$repo/build}
jobs=$(nproc)
log() { printf '[cellsph setup] %s\n' "$*"; }
since() {    # since START: the time elapsed since $SECONDS was START, as "3 min 05 s"
  local s=$((SECONDS - $1))
  if [ "$s" -ge 60 ]; then printf '%d min %02d s' $((s / 60)) $((s % 60)); else printf '%d s' "$s"; fi
}
phase() {    # phase LOG WHAT COMMAND...: run a long step quietly, saying what and how long it took
  local logf=$1 what=$2 start=$SECONDS
  shift 2
  log "$what ..."
  "$@" >"$logf" 2>&1 || { tail -n 40 "$logf" >&2; log "$what failed after $(since "$start") (log: $logf)"; exit 1; }
  log "$what: done in $(since "$start")"
}
progress() {    # progress LOG WHAT: copy a make build's output (stdin) to LOG; every 30 s say its %
  local logf=$1 what=$2 start=$SECONDS next=30 pct=0 line part="" rc
  exec 3>"$logf"
  while :; do
    # wait at most 5 s for a line, so that long silent steps (linking) are reported too
    if IFS= read -r -t 5 line; then
      line=$part$line part=""
      printf '%s\n' "$line" >&3
      if [[ $line =~ ^\[\ *([0-9]+)%\] ]]; then pct=${BASH_REMATCH[1]}; fi
    else
      rc=$?
      if [ "$rc" -le 128 ]; then    # end of output
        [ -z "$part$line" ] || printf '%s\n' "$part$line" >&3
        break
      fi
      part=$part$line    # timed out within a line: keep what came
    fi
    if [ $((SECONDS - start)) -ge "$next" ]; then
      log "$what: $pct % after $(since "$start")"
      next=$((next + 30))
    fi
  done
  exec 3>&-
}
mkdir -p "$cache"

sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)

packages=(build-essential cmake pkg-config openmpi-bin libopenmpi-dev libpng-dev zlib1g-dev
  libeigen3-dev libqhull-dev voro++-dev gnuplot-nox python3 dpkg-dev clang-format
  libgtest-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
install_packages() {
  "${sudo_cmd[@]}" apt-get update -qq &&
    DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
}
if [ ${#missing[@]} -gt 0 ]; then
  phase "$cache/apt.log" "installing Debian packages: ${missing[*]}" install_packages
fi

# Debian's LAMMPS source package, fetched with a private apt set-up under the cache: its sources
# are the deb-src twins of this machine's own deb sources (same mirrors, suites and keys), its
# package lists and caches live in $cache/apt, so the system's apt configuration stays as it is.
fetch_debian_source() {    # (runs under phase's ||, where set -e is off: every step is checked)
  local aptdir=$cache/apt f
  rm -rf "$aptdir/sources.list.d" &&
    mkdir -p "$aptdir/sources.list.d" "$aptdir/lists/partial" "$aptdir/cache/archives/partial" || return
  for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do    # "deb [opts] uri suite comp"
    if [ -f "$f" ]; then sed -n -E 's/^[[:space:]]*deb(-src)?([[:space:]])/deb-src\2/p' "$f"; fi
  done | sort -u >"$aptdir/sources.list" || return
  for f in /etc/apt/sources.list.d/*.sources; do    # deb822 stanzas
    if [ -f "$f" ]; then sed -E 's/^Types:.*/Types: deb-src/' "$f" >"$aptdir/sources.list.d/${f##*/}" || return; fi
  done
  local opts=(-o "Dir::Etc::sourcelist=$aptdir/sources.list" -o "Dir::Etc::sourceparts=$aptdir/sources.list.d"
    -o "Dir::State::Lists=$aptdir/lists" -o "Dir::Cache=$aptdir/cache")
  # as root, apt downloads as the user _apt, who cannot enter root's home where the cache is
  [ "$(id -u)" -ne 0 ] || opts+=(-o APT::Sandbox::User=root)
  # the release this machine runs (bookworm on Debian 12), not whatever newer deb-src is listed
  local codename
  codename=$(. /etc/os-release && echo "${VERSION_CODENAME:-}")
  apt-get "${opts[@]}" update && (cd "$srcroot" && apt-get "${opts[@]}" source "lammps${codename:+/$codename}")
}

# --- LAMMPS: an installed one, or a build of a source tree (cached) --------------------------
if [ -n "${LAMMPS_PREFIX:-}" ]; then
  [ -d "$LAMMPS_PREFIX" ] || { echo "cellsph setup: LAMMPS_PREFIX=$LAMMPS_PREFIX is not a folder" >&2; exit 1; }
  LAMMPS_PREFIX=$(cd "$LAMMPS_PREFIX" && pwd)
  log "installed LAMMPS: $LAMMPS_PREFIX${LAMMPS_SOURCE_DIR:+ (headers from $LAMMPS_SOURCE_DIR)}"
else
  if [ -z "${LAMMPS_SOURCE_DIR:-}" ]; then
    srcroot=$cache/debian-src
    mkdir -p "$srcroot"
    LAMMPS_SOURCE_DIR=$(find "$srcroot" -maxdepth 1 -type d -name 'lammps-*' | head -n 1)
    if [ -z "$LAMMPS_SOURCE_DIR" ]; then
      phase "$cache/apt-source.log" "fetching Debian's LAMMPS source package into $srcroot" fetch_debian_source
      LAMMPS_SOURCE_DIR=$(find "$srcroot" -maxdepth 1 -type d -name 'lammps-*' | head -n 1)
    fi
  fi
  [ -f "$LAMMPS_SOURCE_DIR/src/version.h" ] ||
    { echo "cellsph setup: $LAMMPS_SOURCE_DIR is not a LAMMPS tree (no src/version.h)" >&2; exit 1; }
  LAMMPS_SOURCE_DIR=$(cd "$LAMMPS_SOURCE_DIR" && pwd)
  version=$(sed -n -E 's/^#define LAMMPS_VERSION "(.*)"/\1/p' "$LAMMPS_SOURCE_DIR/src/version.h" | tr -d ' ')
  log "LAMMPS source: $LAMMPS_SOURCE_DIR ($version)"

  host_opts=(-DBUILD_SHARED_LIBS=on -DPKG_PLUGIN=on -DPKG_MOLECULE=on -DPKG_SPH=on -DPKG_OPENMP=on
    -DBUILD_MPI=on -DBUILD_OMP=on -DWITH_PNG=on -DWITH_JPEG=off -DWITH_FFMPEG=off -DWITH_GZIP=on
    -DLAMMPS_EXCEPTIONS=off -DCMAKE_BUILD_TYPE=Release -DBUILD_TOOLS=off -DBUILD_DOC=off)
  if [ -z "${LAMMPS_BUILD_DIR:-}" ]; then
    key=$(printf '%s %s %s' "$LAMMPS_SOURCE_DIR" "$version" "${host_opts[*]}" | sha1sum | cut -c1-10)
    LAMMPS_BUILD_DIR=$cache/lammps-$version-$key
    if [ ! -x "$LAMMPS_BUILD_DIR/lmp" ]; then
      # `cmake --install` of this build goes into the cache too (tools/test-installed.sh), not
      # into LAMMPS's default ~/.local
      phase "$cache/cmake-$key.log" "configuring LAMMPS $version in $LAMMPS_BUILD_DIR" \
        cmake -S "$LAMMPS_SOURCE_DIR/cmake" -B "$LAMMPS_BUILD_DIR" "${host_opts[@]}" \
        -DCMAKE_INSTALL_PREFIX="$cache/installed/${LAMMPS_BUILD_DIR##*/}"
      start=$SECONDS
      log "building LAMMPS $version (once; about 5 min on 2 idle cores, 15 under load) ..."
      cmake --build "$LAMMPS_BUILD_DIR" -j "$jobs" --target lmp 2>&1 |
        progress "$cache/build-$key.log" "building LAMMPS" ||
        { tail -n 40 "$cache/build-$key.log" >&2; log "building LAMMPS failed (log: $cache/build-$key.log)"; exit 1; }
      log "building LAMMPS: done in $(since "$start")"
    fi
  fi
  log "LAMMPS build: $LAMMPS_BUILD_DIR"
fi

# --- the plugin ------------------------------------------------------------------------------
if [ -n "${LAMMPS_PREFIX:-}" ]; then
  # forget what an earlier configure found, so that a changed prefix is searched anew
  host=(-DCMAKE_PREFIX_PATH="$LAMMPS_PREFIX" -DLAMMPS_BUILD_DIR= -DLAMMPS_SOURCE_DIR="${LAMMPS_SOURCE_DIR:-}"
    -U LAMMPS_DIR -U LAMMPS_LIBRARY -U LAMMPS_EXECUTABLE -U '*LAMMPS_PC*')
else
  host=(-DLAMMPS_SOURCE_DIR="$LAMMPS_SOURCE_DIR" -DLAMMPS_BUILD_DIR="$LAMMPS_BUILD_DIR")
fi
phase "$build.cmake.log" "configuring the plugin in $build" \
  cmake -S "$repo" -B "$build" "${host[@]}" -DCMAKE_BUILD_TYPE=Release
phase "$build.build.log" "building the plugin" cmake --build "$build" -j "$jobs"
log "plugin: $build/cellsphplugin.so"
log "environment: source $build/env.sh  (puts lmp on PATH and the plugin on the loader path)"
