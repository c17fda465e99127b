#!/usr/bin/env bash
# The rockspec builds with Debian's luarocks: `luarocks make` into a scratch tree, for
# Lua 5.4 and for LuaJIT (luarocks' Lua 5.1, with LuaJIT's headers), each built from a copy
# of the sources as a release holds them, then require("jostle") from that tree in each and
# load the example level (.tmj: JSON, which a rock built without pugixml reads too).
#   run_rock_test.sh SOURCE_DIR WORK_DIR VERSION
set -euo pipefail
source=$1 work=$2 version=$3
command -v luarocks >/dev/null || { echo "luarocks not found (scripts/setup.sh installs it)"; exit 77; }
rockspec=bindings/lua/jostle-$version-1.rockspec
[ -f "$source/$rockspec" ] || { echo "no $rockspec for version $version"; exit 1; }

# What the rock builds from; the build directory (build.luarocks) is shared by the two
# builds, so the second compiles only the module.
copy=$work/jostle-$version
tree=$work/tree
rm -rf "$copy" "$tree"
mkdir -p "$copy/bindings"
cp -r "$source"/{CMakeLists.txt,CHANGELOG.md,LICENSE,README.md,cmake,include,src} "$copy"
cp -r "$source/bindings/lua" "$copy/bindings"
cd "$copy"

luajit_include=$(pkg-config --variable=includedir luajit 2>/dev/null || echo /usr/include/luajit-2.1)
for lua in 5.4 luajit; do
  if [ $lua = luajit ]; then
    command -v luajit >/dev/null && [ -f "$luajit_include/lua.h" ] \
      || { echo "LuaJIT or its headers missing: its rock is not tried"; continue; }
    luarocks --lua-version 5.1 make --tree "$tree" "$rockspec" LUA_INCDIR="$luajit_include" >/dev/null
    LUA_CPATH="$tree/lib/lua/5.1/?.so" luajit "$source/tests/packaging/drop_box.lua" "$version"
    LUA_CPATH="$tree/lib/lua/5.1/?.so" luajit "$source/tests/packaging/load_level.lua" \
      "$source/examples/levels/level.tmj"
  else
    command -v lua5.4 >/dev/null || { echo "Lua 5.4 missing: its rock is not tried"; continue; }
    luarocks --lua-version 5.4 make --tree "$tree" "$rockspec" >/dev/null
    LUA_CPATH="$tree/lib/lua/5.4/?.so" lua5.4 "$source/tests/packaging/drop_box.lua" "$version"
    LUA_CPATH="$tree/lib/lua/5.4/?.so" lua5.4 "$source/tests/packaging/load_level.lua" \
      "$source/examples/levels/level.tmj"
  fi
done
luarocks --lua-version 5.4 list --tree "$tree" --porcelain | grep -q "^jostle	$version-1" \
  || { echo "luarocks does not list jostle $version-1 in the tree"; exit 1; }
