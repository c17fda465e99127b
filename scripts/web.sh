#!/usr/bin/env bash
# Builds the web page (jostle in WebAssembly, the demo's samples on a Canvas 2D) with
# Debian's emscripten into build-web/, and serves it on 127.0.0.1 (docs/web.md).
#   scripts/web.sh              set up, build, serve on port 8000 (PORT=... for another)
#   scripts/web.sh --build-only set up and build: the page is build-web/page/
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
# Debian's emscripten runs its JavaScript tools with Debian's modules (acorn).
export NODE_PATH=/usr/share/nodejs
emcmake cmake -S . -B build-web -DCMAKE_BUILD_TYPE=Release -DJOSTLE_BUILD_WEB=ON -DJOSTLE_UNITY_LIBRARY=ON \
  -DJOSTLE_WERROR=ON >/dev/null
cmake --build build-web -j"$(nproc)"
[ "${1:-}" = "--build-only" ] && exit 0

port=${PORT:-8000}
echo "web: the page is at http://127.0.0.1:$port/ (Ctrl-C stops the server)"
exec python3 -m http.server --bind 127.0.0.1 --directory build-web/page "$port"
