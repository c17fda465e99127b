#!/usr/bin/env bash
# One version, written in include/jostle/version.h, said the same everywhere else a format
# needs it written: CMake's project version, CHANGELOG.md's newest release, the rockspec's
# name and version, the JavaScript package (once there is one), the jostle program, the
# Lua module (and the JavaScript one: web_js_api_in_node) and the shared library's file name.
#   check_versions.sh SOURCE_DIR BUILD_DIR CMAKE_VERSION
set -euo pipefail
source=$1 build=$2 cmake_version=$3
version=$(sed -n 's/^#define JOSTLE_VERSION_STRING "\(.*\)"$/\1/p' "$source/include/jostle/version.h")
major=$(sed -n 's/^#define JOSTLE_VERSION_MAJOR \([0-9]*\)$/\1/p' "$source/include/jostle/version.h")
minor=$(sed -n 's/^#define JOSTLE_VERSION_MINOR \([0-9]*\)$/\1/p' "$source/include/jostle/version.h")
patch=$(sed -n 's/^#define JOSTLE_VERSION_PATCH \([0-9]*\)$/\1/p' "$source/include/jostle/version.h")
failed=0
expect() { # what, found
  if [ "$2" != "$version" ]; then echo "$1 says \"$2\", version.h \"$version\""; failed=1
  else echo "$1: $2"; fi
}
expect "version.h's numbers" "$major.$minor.$patch"
expect "CMake's project version" "$cmake_version"
expect "CHANGELOG.md's newest release" \
  "$(grep -m1 -oE '^## [0-9]+\.[0-9]+\.[0-9]+' "$source/CHANGELOG.md" | cut -c4-)"
rockspecs=$(cd "$source/bindings/lua" && ls ./*.rockspec)
expect "the rockspec's name" "$(echo "$rockspecs" | sed -n 's|^\./jostle-\(.*\)-[0-9]*\.rockspec$|\1|p')"
expect "the rockspec's version" \
  "$(sed -n 's/^version = "\(.*\)-[0-9]*"$/\1/p' "$source/bindings/lua/$rockspecs")"
for package in "$source"/bindings/web/package.json; do
  [ -f "$package" ] || continue
  expect "$package" "$(sed -n 's/^  "version": "\(.*\)",$/\1/p' "$package")"
done
if [ -x "$build/jostle" ]; then
  expect "jostle --version" "$("$build/jostle" --version | sed 's/^jostle //')"
fi
for lua in lua5.4:5.4 luajit:luajit; do
  interpreter=${lua%%:*} dir=$build/lua/${lua#*:}
  if command -v "$interpreter" >/dev/null && [ -f "$dir/jostle.so" ]; then
    expect "jostle.version in $interpreter" \
      "$(LUA_CPATH="$dir/?.so" "$interpreter" -e 'io.write(require("jostle").version)')"
  fi
done
if [ -e "$build/libjostle.so" ]; then
  expect "the shared library's file" \
    "$(basename "$(readlink -f "$build/libjostle.so")" | sed 's/^libjostle\.so\.//')"
fi
exit $failed
