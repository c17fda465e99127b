#!/usr/bin/env bash
# The Debian package works for each ecosystem's tool: makes it (scripts/package.sh, which
# fails on a lintian error), unpacks it into a scratch root (dpkg -x: the install without
# touching the machine), then, against that tree alone,
#   - builds and runs the C and the C++ consumer with pkg-config (the shared library),
#     and the C one linked with the static library too;
#   - configures, builds and runs the C++ consumer with CMake (find_package(jostle)), and
#     the level library's (tests/consumer/level.cpp) with CMake and pkg-config;
#   - requires the module in Lua 5.4 and in LuaJIT from Debian's module paths;
#   - runs the jostle program.
#   run_deb_test.sh SOURCE_DIR WORK_DIR VERSION
set -euo pipefail
source=$1 work=$2 version=$3
for tool in dpkg-deb lintian pkg-config cpack; do
  command -v $tool >/dev/null || { echo "$tool not found (scripts/setup.sh installs it)"; exit 77; }
done
mkdir -p "$work"
package=$("$source/scripts/package.sh" "$work/build-deb" | tail -1)
echo "package: $package"
dpkg-deb --field "$package" Package Version
[ "$(dpkg-deb --field "$package" Version)" = "$version" ] || { echo "not version $version"; exit 1; }

root=$work/root
rm -rf "$root"
dpkg-deb -x "$package" "$root"
arch=$(dpkg-architecture -qDEB_HOST_MULTIARCH)
libdir=$root/usr/lib/$arch
for f in "$libdir/libjostle.so.0.1" "$libdir/libjostle.a" "$libdir/pkgconfig/jostle.pc" \
         "$libdir/cmake/jostle/jostleConfig.cmake" "$root/usr/include/jostle/jostle.h" \
         "$libdir/libjostle_level.a" "$libdir/pkgconfig/jostle-level.pc" \
         "$root/usr/include/jostle/level.hpp" "$root/usr/include/jostle/level.h" \
         "$libdir/lua/5.1/jostle.so" "$libdir/lua/5.4/jostle.so" "$root/usr/bin/jostle" \
         "$root/usr/share/doc/jostle/copyright" "$root/usr/share/doc/jostle/changelog.gz"; do
  [ -e "$f" ] || { echo "missing from the package: ${f#"$root"}"; exit 1; }
done

export PKG_CONFIG_PATH=$libdir/pkgconfig
# shellcheck source=../pkgconfig/consumers.sh
source "$source/tests/pkgconfig/consumers.sh"
build_pkgconfig_consumers "$source" "$work" cc c++ "" "" ""
# shellcheck disable=SC2046
cc "$source/tests/c/consumer/main.c" -o "$work/c_static" $(pkg-config --cflags jostle) \
  -L"$libdir" -Wl,-Bstatic -ljostle -Wl,-Bdynamic -lstdc++ -lm -pthread
# The shared library is the one the pkg-config programs load.
# (ldd's output read whole: grep -q stopping early would break the pipe under pipefail.)
loaded=$(LD_LIBRARY_PATH=$libdir ldd "$work/c_consumer")
[[ $loaded == *"$libdir/libjostle.so.0.1"* ]] \
  || { echo "c_consumer does not load the package's libjostle.so.0.1: $loaded"; exit 1; }
LD_LIBRARY_PATH=$libdir "$work/c_consumer"
LD_LIBRARY_PATH=$libdir "$work/cxx_consumer"
"$work/c_static"
build_pkgconfig_level_consumer "$source" "$work" c++ "" ""
LD_LIBRARY_PATH=$libdir "$work/level_consumer"

cmake -S "$source/tests/consumer" -B "$work/cmake_consumer" -DCMAKE_PREFIX_PATH="$root/usr" \
  -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/cmake_consumer" >/dev/null
"$work/cmake_consumer/consumer"
"$work/cmake_consumer/level_consumer"

for lua in lua5.4 luajit; do
  if command -v $lua >/dev/null; then
    cpath=$libdir/lua/$([ $lua = luajit ] && echo 5.1 || echo 5.4)/?.so
    LUA_CPATH=$cpath $lua "$source/tests/packaging/drop_box.lua" "$version"
  fi
done

[ "$("$root/usr/bin/jostle" --version)" = "jostle $version" ]
echo "the package works: C, C++ (pkg-config and CMake), levels, Lua 5.4, LuaJIT, jostle $version"
