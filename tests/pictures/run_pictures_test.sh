#!/usr/bin/env bash
# Draws one group of the pictures in docs/ again with the commands of scripts/pictures.sh
# (its --redraw mode) and compares each with the committed one, frame by frame and pixel
# by pixel (compare_pictures). A picture that differs fails the test with its name, the
# first frame that differs and what to run. The render group also checks that every
# command the docs show for drawing a picture into docs/ is one of scripts/pictures.sh's,
# so that what a reader runs draws what they see.
#
#   run_pictures_test.sh render|demo SOURCE_DIR BUILD_DIR COMPARE OUT_DIR
#
# Exits 77 (the test's SKIP_RETURN_CODE) with the reason when the group's program is
# missing: jostle-demo not built (no SDL2), or SDL's offscreen driver unable to open.
set -uo pipefail
group=$1 source_dir=$2 build=$3 compare=$4 out=$5

if [ "$group" = demo ]; then
  demo=$build/demo/jostle-demo
  if [ ! -x "$demo" ]; then
    echo "skipped: jostle-demo is not built (SDL2 missing: libsdl2-dev, scripts/setup.sh)"
    exit 77
  fi
  if ! SDL_VIDEODRIVER=offscreen SDL_RENDER_DRIVER=software "$demo" --frames 1 >/dev/null 2>&1; then
    echo "skipped: jostle-demo cannot open a window with SDL_VIDEODRIVER=offscreen"
    exit 77
  fi
fi

failed=0
if ! "$source_dir/scripts/pictures.sh" --redraw "$out" "$build" "$group"; then
  echo "FAIL: scripts/pictures.sh --redraw $out $build $group: a command failed (above)"
  exit 1
fi
shopt -s nullglob
drawn=("$out"/docs/*)
if [ ${#drawn[@]} -eq 0 ]; then
  echo "FAIL: scripts/pictures.sh drew no $group picture into $out/docs"
  exit 1
fi
for picture in "${drawn[@]}"; do
  name=docs/$(basename "$picture")
  if [ ! -f "$source_dir/$name" ]; then
    echo "FAIL: scripts/pictures.sh draws $name, which is not in the source tree: run" \
      "scripts/pictures.sh and commit it"
    failed=1
    continue
  fi
  "$compare" "$source_dir/$name" "$picture" "$name" || failed=1
done

if [ "$group" = render ]; then
  # Every `./build/jostle render ... --out docs/...` and `./build/demo/jostle-demo ...
  # --screenshot docs/...` in the README and docs/, as written there (up to a closing
  # backquote or the end of the line), must be a line of scripts/pictures.sh.
  while IFS= read -r shown; do
    file=${shown%%:*} rest=${shown#*:}
    where=$file:${rest%%:*}
    command=$(printf '%s\n' "${rest#*:}" | grep -o '\./build/[^`]*' | sed 's/[[:space:]]*$//')
    if ! grep -qxF "  $command" "$source_dir/scripts/pictures.sh"; then
      echo "FAIL: $where shows a command that scripts/pictures.sh does not run:"
      echo "  $command"
      failed=1
    fi
  done < <(cd "$source_dir" && grep -nE '\./build/(jostle render|demo/jostle-demo) .*(--out|--screenshot) docs/' README.md docs/*.md)
fi
exit $failed
