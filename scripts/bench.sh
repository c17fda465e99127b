#!/usr/bin/env bash
# Sets everything up, builds the benchmark (Release, with Box2D 2.4.1 and Chipmunk 7 from
# Debian) and runs it: jostle beside both peers on every benchmark scene. Arguments go to
# jostle-bench (try --help, --quick, --scene pyramid_100, --markdown).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh libbox2d-dev libchipmunk-dev
cmake -S . -B build-bench -DCMAKE_BUILD_TYPE=Release -DJOSTLE_WERROR=ON \
  -DJOSTLE_BUILD_BENCH=ON -DJOSTLE_BUILD_TESTS=OFF >/dev/null
cmake --build build-bench -j"$(nproc)" --target jostle_bench
./build-bench/jostle-bench "$@"
