#!/usr/bin/env bash
# The determinism tests on other CPUs: aarch64 and s390x (big-endian), built by Debian's
# cross compilers and run under qemu-user; they must give the hashes recorded on x86-64
# (tests/cross, docs/reliability.md). About four minutes on two cores.
#   scripts/cross.sh [ARCH...]       (default: aarch64 s390x)
# Installs the cross compilers and qemu-user (scripts/setup.sh) where it can; an
# architecture whose compiler or qemu is still missing is skipped with a message.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh g++-aarch64-linux-gnu g++-s390x-linux-gnu qemu-user >/dev/null || true
arches=("$@")
[ ${#arches[@]} -gt 0 ] || arches=(aarch64 s390x)
for arch in "${arches[@]}"; do
  if ! command -v "$arch-linux-gnu-g++" >/dev/null || ! command -v "qemu-$arch" >/dev/null; then
    echo "cross: $arch skipped: g++-$arch-linux-gnu or qemu-user missing"
    continue
  fi
  build=build-cross-$arch
  cmake -S tests/cross -B "$build" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_TOOLCHAIN_FILE="$PWD/cmake/toolchains/linux-gnu.cmake" -DJOSTLE_CROSS_CPU="$arch" >/dev/null
  cmake --build "$build" -j"$(nproc)" --target determinism_tests >/dev/null
  ctest --test-dir "$build" --output-on-failure
done
