#!/usr/bin/env bash
# Tiled's own conversion: examples/levels/level.tmx exported as JSON by Debian's Tiled
# (tiled --export-map) and the .tmx, each stepped 240 times by `jostle run`, end with every
# body in the same place. Exits 77 (skipped) where Tiled is missing.
#   tiled_export.sh <jostle> <examples/levels> <scratch dir>
set -euo pipefail
jostle=$1
examples=$2
work=$3
if ! command -v tiled >/dev/null; then
  echo "SKIPPED: tiled is not installed (scripts/setup.sh installs it: apt-get install tiled)"
  exit 77
fi
rm -rf "$work"
mkdir -p "$work"
cp "$examples/level.tmx" "$examples/tiles.tsx" "$examples/tiles.png" "$work/"
(cd "$work" && QT_QPA_PLATFORM=offscreen XDG_RUNTIME_DIR="$work" tiled --embed-tilesets --export-map json level.tmx exported.tmj)
# The summary less its file name and its wall time, which differs run to run.
summary() { "$jostle" run "$1" --steps 240 | grep -v -e '^wall time' -e '^scene '; }
from_tmx=$(summary "$work/level.tmx")
from_tmj=$(summary "$work/exported.tmj")
echo "$from_tmx"
if [ "$from_tmx" != "$from_tmj" ]; then
  echo "FAILED: Tiled's JSON export of level.tmx steps differently:"
  echo "$from_tmj"
  exit 1
fi
echo "Tiled's JSON export of level.tmx gives the same level"
