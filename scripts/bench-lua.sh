#!/usr/bin/env bash
# Sets everything up (Debian packages, as scripts/setup.sh installs them), builds the Lua
# modules (Release) and runs bindings/lua/bench/read_positions.lua: one world:step() of
# 40,000 moving bodies beside reading all their positions from Lua with getPosition per
# body, with getPositions into a table, and through LuaJIT's FFI (getPositionsBuffer); under
# LuaJIT, then under Lua 5.4 (no FFI). Arguments go to the script: [bodies [repeats]].
# The figures are in docs/benchmarks.md.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake -S . -B build-bench-lua -DCMAKE_BUILD_TYPE=Release -DJOSTLE_WERROR=ON \
  -DJOSTLE_BUILD_TESTS=OFF -DJOSTLE_BUILD_DEMO=OFF >/dev/null
cmake --build build-bench-lua -j"$(nproc)" --target jostle_lua_luajit jostle_lua_54
LUA_CPATH="build-bench-lua/lua/luajit/?.so" luajit bindings/lua/bench/read_positions.lua "$@"
echo
LUA_CPATH="build-bench-lua/lua/5.4/?.so" lua5.4 bindings/lua/bench/read_positions.lua "$@"
