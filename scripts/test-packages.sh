#!/usr/bin/env bash
# The packages, made from scratch and used (docs/packaging.md): the Debian package (the
# test debian_package: made, checked by lintian, unpacked, built against from C, C++, CMake
# and pkg-config, required from Lua 5.4 and LuaJIT) and the rock (lua_rock: built by
# luarocks for Lua 5.4 and LuaJIT, required). Each compiles the library again, as a user's
# machine does, so they are apart from the test command: about five minutes on two cores.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake -S . -B build-packages -DCMAKE_BUILD_TYPE=Release -DJOSTLE_PACKAGE_TESTS=ON \
  -DJOSTLE_BUILD_DEMO=OFF >/dev/null
ctest --test-dir build-packages -R '^(debian_package|lua_rock)$' --output-on-failure -j"$(nproc)"
