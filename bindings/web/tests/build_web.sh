#!/usr/bin/env bash
# Builds the web module with emscripten: build_web.sh <source dir> <build dir>. Exits 77,
# which ctest reads as skipped, where emscripten or esbuild is not installed.
set -euo pipefail
source_dir=$1
build_dir=$2
if ! command -v emcmake >/dev/null; then
  echo "SKIPPED: emscripten is not installed (scripts/setup.sh installs it: apt-get install emscripten)"
  exit 77
fi
if ! command -v esbuild >/dev/null; then
  echo "SKIPPED: esbuild is not installed (scripts/setup.sh installs it: apt-get install esbuild)"
  exit 77
fi
# Debian's emscripten runs its JavaScript tools with Debian's modules (acorn).
export NODE_PATH=/usr/share/nodejs
emcmake cmake -S "$source_dir" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release \
  -DJOSTLE_BUILD_WEB=ON -DJOSTLE_WERROR=ON -DJOSTLE_UNITY_LIBRARY=ON >/dev/null
cmake --build "$build_dir" -j2
