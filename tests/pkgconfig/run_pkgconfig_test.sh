#!/usr/bin/env bash
# Installs the built jostle into a scratch prefix, then builds the C and the C++ consumer
# programs (tests/c/consumer, tests/consumer) with nothing but the compiler and
# `pkg-config --cflags --libs jostle`, and runs them: each drops a box on a floor; and the
# level library's consumer with jostle-level's, which reads a Tiled map.
#   run_pkgconfig_test.sh BUILD_DIR SOURCE_DIR WORK_DIR CC CXX "CFLAGS" "CXXFLAGS" "LDFLAGS"
set -euo pipefail
build=$1 source=$2 work=$3 cc=$4 cxx=$5 cflags=$6 cxxflags=$7 ldflags=$8
command -v pkg-config >/dev/null || { echo "pkg-config not found (apt-get install pkgconf)"; exit 77; }
rm -rf "$work"
mkdir -p "$work"
cmake --install "$build" --prefix "$work/prefix" >/dev/null
pc_dir=$(dirname "$(find "$work/prefix" -name jostle.pc | head -1)")
export PKG_CONFIG_PATH=$pc_dir
echo "pkg-config --modversion jostle: $(pkg-config --modversion jostle)"
# shellcheck source=consumers.sh
source "$source/tests/pkgconfig/consumers.sh"
build_pkgconfig_consumers "$source" "$work" "$cc" "$cxx" "$cflags" "$cxxflags" "$ldflags"
# -ljostle is the shared library where there is one: the programs load it from the prefix.
export LD_LIBRARY_PATH=$(dirname "$pc_dir")
"$work/c_consumer"
"$work/cxx_consumer"
if [ -f "$pc_dir/jostle-scene.pc" ]; then
  pkg-config --exists --print-errors "jostle-scene = $(pkg-config --modversion jostle)"
  echo "jostle-scene: $(pkg-config --libs jostle-scene)"
fi
if [ -f "$pc_dir/jostle-level.pc" ]; then
  build_pkgconfig_level_consumer "$source" "$work" "$cxx" "$cxxflags" "$ldflags"
  "$work/level_consumer"
fi
