#!/usr/bin/env bash
# The npm package as users get it: packed by `npm pack`, installed from its tarball into an
# empty directory (offline: it has no dependencies), then platformer.ts's level type-checked
# by tsc against the package's declarations and played through `import` and `require`,
# each checked against the C++ version of the level.
#   run.sh <package dir> <jostle-package-platformer> <scratch dir>
# Exits 77 (skipped) where node, npm or tsc is missing.
set -euo pipefail
package_dir=$1
native=$2
work=$3
here=$(cd "$(dirname "$0")" && pwd)
for tool in node npm tsc esbuild; do
  if ! command -v $tool >/dev/null; then
    echo "SKIPPED: $tool is not installed (scripts/setup.sh installs it)"
    exit 77
  fi
done
if [ ! -f "$package_dir/package.json" ]; then
  echo "SKIPPED: no package in $package_dir (the web build makes it where esbuild is installed)"
  exit 77
fi
rm -rf "$work"
mkdir -p "$work/game"
tarball=$(cd "$work" && npm pack --silent "$package_dir")
echo "packed $tarball ($(du -k "$work/$tarball" | cut -f1) KB)"
cd "$work/game"
npm init -y >/dev/null
npm pkg set type=module
npm install --offline --no-audit --no-fund --silent "$work/$tarball"
cp "$here"/platformer.ts "$here"/tsconfig.json "$here"/expect.cjs "$here"/esm.mjs "$here"/cjs.cjs \
   "$here"/*.html "$here"/worker.mjs "$here"/bundle.mjs .
tsc -p .
expected=$("$native")
echo "C++: $expected"
node esm.mjs "$expected"
node cjs.cjs "$expected"
# In a browser: as an ES module, bundled by esbuild (its wasm beside the bundle), in a worker.
esbuild bundle.mjs --bundle --format=esm --log-level=warning --outfile=bundled/game.js
cp node_modules/jostle/jostle.wasm bundled/
node "$here"/browser.cjs . "$expected"
