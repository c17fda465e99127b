#!/usr/bin/env bash
# Makes the Debian package of jostle (docs/packaging.md) and checks it with lintian:
#   scripts/package.sh [BUILD_DIR]      (default build-deb)
# Builds the library, the jostle program and the Lua modules for /usr in BUILD_DIR, runs
# `cpack -G DEB` there and prints the package's path last. Fails on any lintian error.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build-deb}
scripts/setup.sh >/dev/null
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX=/usr \
  -DJOSTLE_BUILD_TESTS=OFF -DJOSTLE_BUILD_DEMO=OFF -DJOSTLE_BUILD_BENCH=OFF >/dev/null
cmake --build "$build" -j"$(nproc)" >/dev/null
(cd "$build" && cpack -G DEB >/dev/null)
package=$(ls "$build"/jostle_*.deb)
# Errors fail; warnings are shown (docs/packaging.md lists the ones left on purpose).
lintian --fail-on error --no-tag-display-limit "$package" >&2 || {
  echo "lintian found errors in $package" >&2
  exit 1
}
echo "$package"
