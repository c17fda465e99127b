#!/usr/bin/env bash
# The determinism tests on other CPUs: aarch64 and s390x (big-endian), built by Debian's
# cross compilers and run under qemu-user; they must give the hashes recorded on x86-64,
# a snapshot's bytes among them (tests/cross, docs/reliability.md). Part of
# scripts/test.sh; about two and a half minutes on two cores.
#   scripts/cross.sh [ARCH...]       (default: aarch64 s390x)
# Installs the cross compilers and qemu-user (scripts/setup.sh) where it can; an
# architecture whose compiler or qemu is still missing is skipped with a message.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh g++-aarch64-linux-gnu g++-s390x-linux-gnu qemu-user >/dev/null || true
arches=("$@")
[ ${#arches[@]} -gt 0 ] || arches=(aarch64 s390x)
ready=()
for arch in "${arches[@]}"; do
  if ! command -v "$arch-linux-gnu-g++" >/dev/null || ! command -v "qemu-$arch" >/dev/null; then
    echo "cross: $arch skipped: g++-$arch-linux-gnu or qemu-user missing"
    continue
  fi
  # -O1: the bits are the same at every level (-ffp-contract=off), and it compiles faster
  # than qemu runs -O3's fewer instructions; a unity build, three times faster still.
  cmake -S tests/cross -B "build-cross-$arch" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" -DCMAKE_C_FLAGS_RELEASE="-O1 -DNDEBUG" \
    -DJOSTLE_UNITY_LIBRARY=ON \
    -DCMAKE_TOOLCHAIN_FILE="$PWD/cmake/toolchains/linux-gnu.cmake" -DJOSTLE_CROSS_CPU="$arch" >/dev/null
  ready+=("$arch")
done
[ ${#ready[@]} -gt 0 ] || exit 0

# The CPUs side by side, the cores shared between them: first the builds, then the tests
# (two shards a CPU), all at once.
jobs=$(( $(nproc) / ${#ready[@]} ))
[ "$jobs" -ge 1 ] || jobs=1
side_by_side() { # COMMAND... with ARCH in it replaced by each CPU's name
  local pids=() status=0
  for arch in "${ready[@]}"; do
    "${@//ARCH/$arch}" >"build-cross-$arch/cross.log" 2>&1 &
    pids+=($!)
  done
  for i in "${!ready[@]}"; do
    wait "${pids[$i]}" || status=1
    cat "build-cross-${ready[$i]}/cross.log"
  done
  return $status
}
side_by_side cmake --build build-cross-ARCH -j"$jobs" --target determinism_tests
side_by_side ctest --test-dir build-cross-ARCH --output-on-failure -j2
