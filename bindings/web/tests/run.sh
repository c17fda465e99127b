#!/usr/bin/env bash
# Runs a test of the web module in Node: run.sh <web build dir> <script.js> [args...].
# Exits 77 (skipped) with the reason where Node or the module is missing.
set -euo pipefail
web_dir=$1
shift
if ! command -v node >/dev/null; then
  echo "SKIPPED: node is not installed (scripts/setup.sh installs nodejs)"
  exit 77
fi
if [ ! -f "$web_dir/page/jostle-web.wasm" ]; then
  echo "SKIPPED: the web module is not built in $web_dir (web_module: emscripten missing?)"
  exit 77
fi
export NODE_PATH=/usr/share/nodejs
exec node "$@"
