#!/usr/bin/env bash
# Renders the README's pictures from the shipped scenes with `jostle render`.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
./build/jostle render examples/scenes/tutorial.json --solver physical --out docs/tutorial.gif \
  --steps 240 --every 3
./build/jostle render examples/scenes/pyramid.json --out docs/pyramid.png --steps 240
./build/jostle render examples/scenes/slopes.json --out docs/slopes.gif --steps 300 --every 3
echo "pictures: wrote docs/tutorial.gif, docs/pyramid.png and docs/slopes.gif"
