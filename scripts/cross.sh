#!/usr/bin/env bash
# The determinism tests on other CPUs: aarch64 and s390x (big-endian), built by Debian's
# cross compilers and run under qemu-user; they must give the hashes recorded on x86-64
# (tests/cross, docs/reliability.md). Part of scripts/test.sh.
#   scripts/cross.sh [ARCH...]       (default: aarch64 s390x)
# An architecture whose compiler or qemu is missing is skipped with a message.
set -euo pipefail
cd "$(dirname "$0")/.."
arches=("$@")
[ ${#arches[@]} -gt 0 ] || arches=(aarch64 s390x)
for arch in "${arches[@]}"; do
  if ! command -v "$arch-linux-gnu-g++" >/dev/null || ! command -v "qemu-$arch" >/dev/null; then
    echo "cross: $arch skipped: g++-$arch-linux-gnu or qemu-user missing (scripts/setup.sh installs them)"
    continue
  fi
  build=build-cross-$arch
  cmake -S tests/cross -B "$build" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_TOOLCHAIN_FILE="$PWD/cmake/toolchains/$arch-linux-gnu.cmake" >/dev/null
  cmake --build "$build" -j"$(nproc)" --target determinism_tests >/dev/null
  ctest --test-dir "$build" --output-on-failure
done
