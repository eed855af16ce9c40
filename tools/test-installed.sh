#!/usr/bin/env bash
# Build the plugin against an *installed* LAMMPS and run the test suite with it, in
# build-installed/ (CELLSPH_BUILD_INSTALLED). Extra arguments go to ctest (e.g. -R plugin/).
#
#   LAMMPS_PREFIX=<prefix> [LAMMPS_SOURCE_DIR=<tree>] bash tools/test-installed.sh
#       test that installed LAMMPS (a `cmake --install` prefix, an HPC module); the source tree of
#       the same version is needed when the install lacks headers (29 Sep 2021 installs only some)
#   bash tools/test-installed.sh
#       test the LAMMPS that tools/setup.sh built (run it first): `cmake --install` it into
#       <cache>/installed/<build name> and build and test the plugin from that install alone. The
#       build tree is hidden meanwhile: in a private mount namespace (root only) an empty folder
#       covers it, so whatever still reached into it would fail.
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cache=${CELLSPH_CACHE:-$HOME/.cache/cellsph}
build=${CELLSPH_BUILD_INSTALLED:-$repo/build-installed}
log() { printf '[cellsph test-installed] %s\n' "$*"; }
start=$SECONDS
hide=""

if [ -z "${LAMMPS_PREFIX:-}" ]; then
  # the LAMMPS of the set-up, as recorded by the plugin build of tools/setup.sh
  main=${CELLSPH_BUILD:-$repo/build}
  cached() { sed -n "s/^$1:[A-Z]*=//p" "$main/CMakeCache.txt" 2>/dev/null; }
  lammps_build=$(cached LAMMPS_BUILD_DIR)
  LAMMPS_SOURCE_DIR=$(cached LAMMPS_SOURCE_DIR)
  case $lammps_build in
    "$cache"/lammps-*) ;;
    *) echo "cellsph test-installed: no LAMMPS built by tools/setup.sh in $cache (run it first)," \
      "or give LAMMPS_PREFIX=<an installed LAMMPS>" >&2; exit 1 ;;
  esac
  LAMMPS_PREFIX=$cache/installed/${lammps_build##*/}
  mkdir -p "$LAMMPS_PREFIX"
  # LAMMPS fixes its install prefix when configured (liblammps.pc, the Python module): builds of
  # older set-ups point it at ~/.local; move it into the cache (no recompilation)
  if ! grep -qxF "CMAKE_INSTALL_PREFIX:PATH=$LAMMPS_PREFIX" "$lammps_build/CMakeCache.txt"; then
    log "setting the install prefix of $lammps_build to $LAMMPS_PREFIX"
    cmake -S "$LAMMPS_SOURCE_DIR/cmake" -B "$lammps_build" -DCMAKE_INSTALL_PREFIX="$LAMMPS_PREFIX" \
      >"$LAMMPS_PREFIX.configure.log" 2>&1 || { tail -n 30 "$LAMMPS_PREFIX.configure.log" >&2; exit 1; }
  fi
  cmake --install "$lammps_build" >"$LAMMPS_PREFIX.install.log" 2>&1 ||
    { tail -n 30 "$LAMMPS_PREFIX.install.log" >&2; exit 1; }
  log "installed $lammps_build into $LAMMPS_PREFIX"
  hide=$lammps_build
fi
LAMMPS_PREFIX=$(cd "$LAMMPS_PREFIX" && pwd)

# configure, build and test; run with the LAMMPS build tree (if any) covered
build_and_test() {
  cmake -S "$repo" -B "$build" -DCMAKE_PREFIX_PATH="$LAMMPS_PREFIX" -DLAMMPS_BUILD_DIR= \
    -DLAMMPS_SOURCE_DIR="${LAMMPS_SOURCE_DIR:-}" -U LAMMPS_DIR -U LAMMPS_LIBRARY \
    -U LAMMPS_EXECUTABLE -U '*LAMMPS_PC*' -DCMAKE_BUILD_TYPE=Release >"$build.cmake.log" 2>&1 ||
    { cat "$build.cmake.log" >&2; return 1; }
  grep '^-- cellsph:' "$build.cmake.log"
  cmake --build "$build" -j "$(nproc)" >"$build.build.log" 2>&1 || { tail -n 60 "$build.build.log" >&2; return 1; }
  log "plugin built against $LAMMPS_PREFIX ($((SECONDS - start)) s); running the tests"
  (cd "$build" && ctest --output-on-failure -j "$(nproc)" "$@")
}
export -f build_and_test log
export repo build LAMMPS_PREFIX LAMMPS_SOURCE_DIR start

if [ -n "$hide" ] && [ "$(id -u)" -eq 0 ] && unshare --mount true 2>/dev/null; then
  empty=$(mktemp -d "$cache/empty.XXXXXX")
  log "hiding $hide (an empty folder over it, in this test's own mount namespace)"
  unshare --mount --propagation private bash -c \
    'set -euo pipefail; mount --bind "$1" "$2"; [ ! -e "$2/CMakeCache.txt" ]; shift 2; build_and_test "$@"' \
    _ "$empty" "$hide" "$@"
  rmdir "$empty"
else
  [ -z "$hide" ] || log "cannot hide $hide here (needs root and mount namespaces); testing without"
  build_and_test "$@"
fi

# nothing the plugin build made may point into the LAMMPS build tree
if [ -n "$hide" ] && grep -l -w -F "$hide" "$build/CMakeCache.txt" "$build/bin/lmp" "$build/env.sh"; then
  echo "cellsph test-installed: the files above refer to the LAMMPS build tree $hide" >&2
  exit 1
fi
log "done in $((SECONDS - start)) s"
