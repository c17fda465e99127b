#!/usr/bin/env bash
# Makes the npm package's tarball (docs/javascript.md): sets up, builds the web module
# with Debian's emscripten into build-web/ (which fills build-web/npm/jostle/: the ES
# module, the CommonJS file, the wasm, the TypeScript declarations), then `npm pack` over
# that directory, into build-web/. Prints the tarball's path.
#   scripts/npm-pack.sh     → build-web/jostle-<version>.tgz
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/web.sh --build-only >&2
cd build-web
tarball=$(npm pack --silent npm/jostle)
echo "$PWD/$tarball"
