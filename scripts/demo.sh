#!/usr/bin/env bash
# Sets everything up, builds, runs the tutorial's scene with the jostle program, and
# shows the samples: in a window (jostle-demo, docs/demo.md) when a display is there,
# else as a GIF drawn headless by `jostle render`.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
./build/jostle run examples/scenes/tutorial.json --steps 600

demo=./build/demo/jostle-demo
# A display variable is not enough: it may name a server that is gone. --probe opens a
# hidden window and says whether that worked.
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ] && [ -x "$demo" ] && "$demo" --probe; then
  exec "$demo" "$@"
fi
./build/jostle render examples/scenes/tutorial.json --solver physical --out build/demo.gif \
  --steps 240 --every 3
echo "demo: no display to open a window on; the tutorial's scene is drawn in build/demo.gif"
