#!/usr/bin/env bash
# Sets everything up, builds, and runs the whole test suite twice: the Release build
# (g++), then the same tests built by clang with AddressSanitizer and
# UndefinedBehaviorSanitizer (the asan preset in CMakePresets.json), where the fuzzers
# also run for a short while, then the tests of worlds stepped on several threads under
# ThreadSanitizer (the tsan preset). Any sanitizer report fails its test. Last, the
# determinism tests built for aarch64 and s390x and run under qemu-user (scripts/cross.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)"

cmake --preset asan >/dev/null
cmake --build --preset asan -j"$(nproc)"
ctest --preset asan -j"$(nproc)"

cmake --preset tsan >/dev/null
cmake --build --preset tsan -j"$(nproc)"
ctest --preset tsan -j"$(nproc)"

scripts/cross.sh
