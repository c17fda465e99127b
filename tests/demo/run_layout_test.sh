#!/usr/bin/env bash
# Checks that jostle-demo's samples are laid out so that what one reads stays readable
# and what moves has room to: no body is drawn over a pane's title (or, with debug
# drawing on, over the legend's words), and the platformer's lift rises and sinks through
# a shaft that no wall or ledge crosses.
#
#   run_layout_test.sh DEMO CHECKER OUT_DIR
#
# Headless, on SDL's offscreen video driver; skipped (77) where SDL cannot open a window
# there (offscreen, in report_checks.sh).
set -uo pipefail
demo=$1 checker=$2 out=$3

# shellcheck source-path=SCRIPTDIR source=report_checks.sh
. "$(dirname "$0")/report_checks.sh"
offscreen
mkdir -p "$out"

# --- The platformer's lift (sample 2). A kinematic body passes through static ones, so
# only the level's layout keeps its path clear; --report counts the steps after which a
# kinematic body overlapped a static one by more than touching. The lift goes from
# y 520 up to 230 and back at 90 px/s, 1.5 px a step: 194 steps each way, so 400 frames
# hold a whole round trip, past the steps, the ledge of row 7 and the pit's sides.
run --sample 2 --frames 400
expect kinematic_in_static 0 "platformer: the lift's shaft is clear all the way up and down"

# --- Titles. The window is 1280 x 720, with a header of 48 pixels, a footer of 24 and
# gaps of 4 around the panes: one pane is 1272 wide at x 4, two are 634 wide at x 4 and
# 642. Each pane's title is in a band at its top, from y 48 to 73 (26 rows, the last a
# line): inside its border, from y 49 to 72, there is the title and nothing else. In
# samples 5 and 6 the walls reach above the pane's view (they were drawn across the
# title); in sample 4 boxes rain in from above it.
title_colour=787c87 # kTextDim (palette.hpp)
# Bodies, filled and outlined (kTypeColours, 60% of each for outlines, dynamic bodies
# asleep at 55% with debug drawing on, bullets outlined white).
body_colours="969696 5a5a5a 4682e6 2a4e8a f0963c 905a24 845221 ffffff"
# no_bodies WHY FILE X0 Y0 X1 Y1: no pixel of a body's colour in the rectangle.
no_bodies() {
  local colour
  for colour in $body_colours; do
    pixels "$1 (no $colour)" "$2" "$colour" "$3" "$4" "$5" "$6" 0
  done
}
for sample in 1 2 3 4 5 6 7; do
  panes="4:1272"
  [ "$sample" = 1 ] && panes="4:634 642:634"
  for debug in "" debug; do
    shot="$out/sample-$sample${debug:+-$debug}.bmp"
    rm -f "$shot"
    input=${debug:+2 key-press Tab}
    "$demo" --sample "$sample" --frames 60 --screenshot "$shot" ${input:+--input "$input"} \
      >/dev/null || { echo "FAIL: jostle-demo could not save $shot" >&2; failed=1; continue; }
    for pane in $panes; do
      x0=$((${pane%:*} + 1)) x1=$((${pane%:*} + ${pane#*:} - 2))
      why="sample $sample${debug:+ (debug)}, title band of the pane at x ${pane%:*}"
      no_bodies "$why" "$shot" "$x0" 49 "$x1" 72
      title=$(count "$shot" $title_colour "$x0" 49 "$x1" 72)
      if [ "${title//error/0}" -gt 0 ]; then
        echo "ok: $why: the title is drawn ($title pixels)"
      else
        echo "FAIL: $why: no title pixels" >&2
        failed=1
      fi
    done
  done
done

# --- The legend (debug drawing, sample 6). Its two lines of words are drawn under the
# title from y 78 (the band's 26 rows and 4 more); the crates' left wall, from x 40 to
# 62, crosses them. Over the words (the legend's first line runs to x 400) the wall
# gives way to the background.
no_bodies "crates (debug): the legend's words, where the wall crosses them" \
  "$out/sample-6-debug.bmp" 30 76 70 97
exit "$failed"
