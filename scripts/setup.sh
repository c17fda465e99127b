#!/usr/bin/env bash
# Installs what jostle needs to build and test, from Debian's packages, and any further
# packages named as arguments (scripts/bench.sh adds the peers). Safe to run again:
# packages already there are not fetched twice.
set -euo pipefail

packages=(
  cmake g++ make          # the build
  pkgconf                 # the installed package is tested through pkg-config too
  dpkg-dev lintian luarocks  # the Debian package and the rock (scripts/package.sh)
  libgtest-dev libgmock-dev  # tests
  nlohmann-json3-dev      # scene files
  libpugixml-dev zlib1g-dev libzstd-dev  # Tiled's maps: .tmx, compressed tile layers
  tiled                   # the example level is checked against Tiled's own export
  libcli11-dev            # the jostle program's command line
  libpng-dev libgif-dev   # jostle render's PNG and GIF files
  libsdl2-dev             # jostle-demo's window
  xvfb xauth              # the demo's test runs it in a virtual X server (xvfb-run)
  liblua5.4-dev libluajit-5.1-dev lua5.4 luajit  # the Lua module and its tests
  love                    # the LÖVE example runs in the tests
  clang libclang-rt-14-dev  # the sanitizer build and the fuzzers (libFuzzer)
  valgrind                # memcheck over a part of the suite
  emscripten nodejs       # the web page's module (scripts/web.sh) and its tests in Node
  esbuild node-typescript # the npm package: bundled by esbuild, its types checked by tsc (npm comes with nodejs)
  chromium python3        # the page's tests in headless Chromium; web.sh serves the page
  "$@"
)

missing=()
for p in "${packages[@]}"; do
  dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "setup: installing ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
fi
