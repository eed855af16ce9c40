#!/usr/bin/env bash
# Set up cellsph on Debian 12: system packages, a plugin-capable LAMMPS (cached outside the work
# tree), and the plugin itself. Idempotent: a second run takes seconds.
#
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

sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)

packages=(build-essential cmake pkg-config openmpi-bin libopenmpi-dev libpng-dev zlib1g-dev
  libeigen3-dev voro++-dev gnuplot-nox python3 dpkg-dev clang-format)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  log "installing Debian packages: ${missing[*]}"
  mkdir -p "$cache"
  { "${sudo_cmd[@]}" apt-get update -qq &&
    DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"; } \
    >"$cache/apt.log" 2>&1 || { tail -n 30 "$cache/apt.log" >&2; exit 1; }
fi

# --- LAMMPS source --------------------------------------------------------------------------
if [ -z "${LAMMPS_SOURCE_DIR:-}" ]; then
  srcroot=$cache/debian-src
  mkdir -p "$srcroot"
  LAMMPS_SOURCE_DIR=$(find "$srcroot" -maxdepth 1 -type d -name 'lammps-*' | head -n 1)
  if [ -z "$LAMMPS_SOURCE_DIR" ]; then
    # turn on deb-src in the machine's existing apt sources (no host name is written here)
    if ! apt-get indextargets --format '$(CREATED_BY)' | grep '^Sources$' >/dev/null; then
      log "enabling deb-src in the existing apt sources"
      for f in /etc/apt/sources.list.d/*.sources; do
        [ -e "$f" ] || continue
        "${sudo_cmd[@]}" sed -i -E 's/^Types:[[:space:]]*deb[[:space:]]*$/Types: deb deb-src/' "$f"
      done
      if [ -f /etc/apt/sources.list ]; then
        grep -E '^deb[[:space:]]' /etc/apt/sources.list | sed 's/^deb /deb-src /' |
          while read -r line; do
            grep -qxF "$line" /etc/apt/sources.list || echo "$line" | "${sudo_cmd[@]}" tee -a /etc/apt/sources.list >/dev/null
          done
      fi
      "${sudo_cmd[@]}" apt-get update -qq >"$cache/apt.log" 2>&1
    fi
    log "fetching the Debian LAMMPS source package into $srcroot"
    # the release this machine runs (bookworm on Debian 12), not whatever newer deb-src is listed
    codename=$(. /etc/os-release && echo "${VERSION_CODENAME:-}")
    (cd "$srcroot" && apt-get source -qq "lammps${codename:+/$codename}" >/dev/null)
    LAMMPS_SOURCE_DIR=$(find "$srcroot" -maxdepth 1 -type d -name 'lammps-*' | head -n 1)
  fi
fi
[ -f "$LAMMPS_SOURCE_DIR/src/version.h" ] ||
  { echo "cellsph setup: $LAMMPS_SOURCE_DIR is not a LAMMPS tree (no src/version.h)" >&2; exit 1; }
LAMMPS_SOURCE_DIR=$(cd "$LAMMPS_SOURCE_DIR" && pwd)
version=$(sed -n -E 's/^#define LAMMPS_VERSION "(.*)"/\1/p' "$LAMMPS_SOURCE_DIR/src/version.h" | tr -d ' ')
log "LAMMPS source: $LAMMPS_SOURCE_DIR ($version)"

# --- LAMMPS build (cached, keyed by version and options) -------------------------------------
host_opts=(-DBUILD_SHARED_LIBS=on -DPKG_PLUGIN=on -DPKG_MOLECULE=on -DPKG_SPH=on -DPKG_OPENMP=on
  -DBUILD_MPI=on -DBUILD_OMP=on -DWITH_PNG=on -DWITH_JPEG=off -DWITH_FFMPEG=off -DWITH_GZIP=on
  -DLAMMPS_EXCEPTIONS=off -DCMAKE_BUILD_TYPE=Release -DBUILD_TOOLS=off -DBUILD_DOC=off)
if [ -z "${LAMMPS_BUILD_DIR:-}" ]; then
  key=$(printf '%s %s %s' "$LAMMPS_SOURCE_DIR" "$version" "${host_opts[*]}" | sha1sum | cut -c1-10)
  LAMMPS_BUILD_DIR=$cache/lammps-$version-$key
  if [ ! -x "$LAMMPS_BUILD_DIR/lmp" ]; then
    log "building LAMMPS $version in $LAMMPS_BUILD_DIR (once; several minutes)"
    cmake -S "$LAMMPS_SOURCE_DIR/cmake" -B "$LAMMPS_BUILD_DIR" "${host_opts[@]}" >"$cache/cmake-$key.log"
    cmake --build "$LAMMPS_BUILD_DIR" -j "$jobs" --target lmp >"$cache/build-$key.log" 2>&1 ||
      { tail -n 40 "$cache/build-$key.log" >&2; exit 1; }
  fi
fi
log "LAMMPS build: $LAMMPS_BUILD_DIR"

# --- the plugin ------------------------------------------------------------------------------
cmake -S "$repo" -B "$build" -DLAMMPS_SOURCE_DIR="$LAMMPS_SOURCE_DIR" \
  -DLAMMPS_BUILD_DIR="$LAMMPS_BUILD_DIR" -DCMAKE_BUILD_TYPE=Release >"$build.cmake.log" 2>&1 ||
  { cat "$build.cmake.log" >&2; exit 1; }
cmake --build "$build" -j "$jobs" >"$build.build.log" 2>&1 || { tail -n 60 "$build.build.log" >&2; exit 1; }
log "plugin: $build/cellsphplugin.so"
log "environment: source $build/env.sh  (puts lmp on PATH and the plugin on the loader path)"
