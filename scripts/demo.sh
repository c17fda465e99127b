#!/usr/bin/env bash
# Sets everything up, builds, runs the tutorial's scene with the jostle program, and
# shows the samples: in a window (jostle-demo, docs/demo.md) when a display is there,
# else drawn headless into build/demo-samples/: a screenshot of every sample on SDL's
# offscreen driver, and the tutorial's scene as a GIF by `jostle render`.
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

out=build/demo-samples
mkdir -p "$out"
./build/jostle render examples/scenes/tutorial.json --solver physical --legend \
  --out "$out/tutorial.gif" --steps 240 --every 3
drawn=("$out/tutorial.gif: the tutorial's scene, physical model, 4 s")
# Each sample after 3 s (180 frames of 1/60 s), as the window shows it, saved by the demo
# itself on SDL's offscreen video driver and software renderer: no display needed.
export SDL_VIDEODRIVER=offscreen SDL_RENDER_DRIVER=software
if [ -x "$demo" ] && "$demo" --frames 1 >/dev/null 2>&1; then
  for sample in 1 2 3 4 5 6 7 8 9; do
    shot=$out/sample-$sample.png
    name=$("$demo" --sample "$sample" --frames 180 --screenshot "$shot" --report |
      awk '$1 == "sample" { print $2 }')
    mv "$shot" "$out/sample-$sample-$name.png"
    drawn+=("$out/sample-$sample-$name.png: sample $sample, $name")
  done
else
  echo "demo: jostle-demo cannot run headless here (not built, or SDL's offscreen driver" \
    "fails): only the tutorial's GIF is drawn" >&2
fi
echo "demo: no display to open a window on; drawn instead:"
printf '  %s\n' "${drawn[@]}"
echo "demo: any sample at any moment, keys and all: SDL_VIDEODRIVER=offscreen $demo" \
  "--sample N --frames F [--input SCRIPT] --screenshot FILE.png (docs/demo.md)"
