#!/usr/bin/env bash
# Draws every picture in docs/ that jostle's own programs draw: the GIFs and the PNG of
# `jostle render`, and the demo's screenshots. Each has one command below, run from the
# top of the source tree. The tests pictures_render and pictures_demo (ctest) run the same
# commands into the build directory and fail when a frame differs from the committed
# picture: after a change to the simulation or the drawing, run this and commit docs/.
#
#   scripts/pictures.sh                     set up, build (build/), draw them into docs/
#   scripts/pictures.sh --web               the same, then docs/web.png too (below)
#   scripts/pictures.sh --redraw DIR BUILD render|demo
#                                           the tests' way: draw one group into DIR/docs/
#                                           with the programs in BUILD; nothing is set up
#                                           or built
#
# docs/web.png is the web page in headless Chromium, saved by the test web_browser_session
# (it builds the module with emscripten first: minutes) after a second and a half of real
# time, with the step time in its header, so no test can compare it pixel for pixel; --web
# runs that test and copies its screenshot. docs/benchmarks.png is plotted by
# scripts/plot-bench.sh.
set -euo pipefail

# `jostle render`, with the key to its colours (--legend).
render_pictures() {
  ./build/jostle render examples/scenes/tutorial.json --solver physical --legend --out docs/tutorial.gif --steps 240 --every 3
  ./build/jostle render examples/scenes/slopes.json --legend --out docs/slopes.gif --steps 300 --every 3
  ./build/jostle render examples/scenes/pyramid.json --legend --out docs/pyramid.png --steps 240
  ./build/jostle render examples/levels/level.tmx --legend --out docs/level.png --steps 120
  ./build/jostle render examples/levels/level.tmx --debug --out docs/level-debug.png --steps 120
}

# The demo without a display: SDL's offscreen video driver and its software renderer, so
# that no GPU or window system has a say in the pixels. With --frames every frame is 1/60
# s, and keys come from --input (docs/demo.md), so a screenshot is the same every time.
demo_pictures() (
  export SDL_VIDEODRIVER=offscreen SDL_RENDER_DRIVER=software
  ./build/demo/jostle-demo --sample 2 --frames 50 --input "30 key-down Right; 30 key-press Space" --screenshot docs/demo-platformer.png
  ./build/demo/jostle-demo --sample 6 --frames 150 --input "2 key-press Tab; 30 key-down Right" --screenshot docs/demo-crates-debug.png
)

if [ "${1:-}" = "--redraw" ]; then
  if [ $# -ne 4 ] || { [ "$4" != render ] && [ "$4" != demo ]; }; then
    echo "usage: scripts/pictures.sh --redraw DIR BUILD render|demo" >&2
    exit 2
  fi
  source_dir=$(cd "$(dirname "$0")/.." && pwd)
  out=$2
  build=$(cd "$3" && pwd)
  # A tree of its own that looks like the source tree to the commands above: its build/
  # is BUILD, its examples/ the source's, its docs/ empty.
  rm -rf "$out"
  mkdir -p "$out/docs"
  ln -s "$build" "$out/build"
  ln -s "$source_dir/examples" "$out/examples"
  cd "$out"
  "${4}_pictures"
  exit 0
fi

web=0
case "${1:-}" in
  "") ;;
  --web) web=1 ;;
  *) echo "usage: scripts/pictures.sh [--web] | --redraw DIR BUILD render|demo" >&2; exit 2 ;;
esac
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
render_pictures
if [ -x build/demo/jostle-demo ]; then
  demo_pictures
else
  echo "pictures: jostle-demo is not built (SDL2 missing?): its screenshots are left as they were" >&2
fi
if [ "$web" = 1 ]; then
  shot=build/bindings/web/tests/screenshots/tutorial.png
  rm -f "$shot"
  ctest --test-dir build -R '^web_browser_session$' --output-on-failure
  if [ -f "$shot" ]; then
    cp "$shot" docs/web.png
  else
    echo "pictures: web_browser_session saved no screenshot (skipped?): docs/web.png is left as it was" >&2
  fi
fi
echo "pictures: drew docs/ again; see what changed (git status docs/), look at it, commit it"
