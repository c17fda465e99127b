#!/usr/bin/env bash
# Sets everything up, builds the benchmarks (Release, with Box2D 2.4.1 and Chipmunk 7 from
# Debian) and runs one: jostle beside both peers on every benchmark scene, or with `load`
# first, scene files of a million bodies loaded (jostle-bench-load), or with `snapshots`
# first, the size and speed of snapshots (jostle-bench-snapshots), or with `dispatch`
# first, what handing a loop to the workers costs (jostle-bench-dispatch), or with
# `levels` first, loading Tiled maps (jostle-bench-levels), or with `web-scenes DIR` first,
# the web benchmark's scenes written as files (scripts/bench-web.sh).
# The other arguments
# go to the program (try --help, --quick, --scene pyramid_100, --markdown; load --bodies N).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh libbox2d-dev libchipmunk-dev
# JOSTLE_BENCH_BOX2D3=<prefix> in the environment: Box2D v3 installed there joins as the
# engine box2d3 (docs/benchmarks.md says how to build it; Debian has only 2.4.1).
cmake -S . -B build-bench -DCMAKE_BUILD_TYPE=Release -DJOSTLE_WERROR=ON \
  -DJOSTLE_BUILD_BENCH=ON -DJOSTLE_BUILD_TESTS=OFF \
  -DJOSTLE_BENCH_BOX2D3="${JOSTLE_BENCH_BOX2D3:-}" >/dev/null
if [[ "${1:-}" == snapshots ]]; then
  shift
  cmake --build build-bench -j"$(nproc)" --target jostle_bench_snapshots
  exec ./build-bench/jostle-bench-snapshots "$@"
fi
if [[ "${1:-}" == dispatch ]]; then
  shift
  cmake --build build-bench -j"$(nproc)" --target jostle_bench_dispatch
  exec ./build-bench/jostle-bench-dispatch "$@"
fi
if [[ "${1:-}" == levels ]]; then
  shift
  cmake --build build-bench -j"$(nproc)" --target jostle_bench_levels
  exec ./build-bench/jostle-bench-levels "$@"
fi
if [[ "${1:-}" == web-scenes ]]; then
  shift
  cmake --build build-bench -j"$(nproc)" --target jostle_web_scenes
  exec ./build-bench/jostle-web-scenes "$@"
fi
if [[ "${1:-}" == load ]]; then
  shift
  cmake --build build-bench -j"$(nproc)" --target jostle_bench_load
  exec ./build-bench/jostle-bench-load "$@"
fi
cmake --build build-bench -j"$(nproc)" --target jostle_bench
./build-bench/jostle-bench "$@"
