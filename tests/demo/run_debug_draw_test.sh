#!/usr/bin/env bash
# Checks that jostle-demo's debug drawing draws what it says (docs/demo.md): the pairs
# that touch, counted by --report and drawn as dots and normals where the boxes meet, the
# broadphase picture (which grid, its cell size) and the library's drawing of its cells,
# and sleeping bodies dimmed. Every expected number is worked out below from the samples' bodies and the
# documented rules; the screenshots are read back with check_screenshot --count.
#
#   run_debug_draw_test.sh DEMO CHECKER OUT_DIR
#
# Runs headless on SDL's offscreen video driver, as run_input_test.sh does; exits 77 (the
# test's SKIP_RETURN_CODE) only if SDL cannot open an offscreen window.
set -uo pipefail
demo=$1 checker=$2 out=$3

# shellcheck source-path=SCRIPTDIR source=report_checks.sh
. "$(dirname "$0")/report_checks.sh"
offscreen
mkdir -p "$out"

# --- Touching pairs, as --report counts them (all that debug drawing draws).
#
# Crates (sample 6): a floor with its top at y 500 (x from -20 to 1020), walls whose inner
# faces are at x 0 and 1000, four crates 56 px wide at x 240, 410, 580, 750 (from 212 to
# 778, 114 px apart) and the player 24 px wide at x 80 (68 to 92). They start 2 to 8 px
# above the floor and land within the first 10 steps; none reaches another or a wall. So
# once settled, 5 pairs touch: each of the five on the floor. Contacts that *began* in the
# last step would be none by frame 90: this counts the pairs that still touch.
run --sample 6 --frames 90
expect contacts 5 "crates: the four crates and the player rest on the floor"
# A jump at frame 30 leaves the floor (the apex is 0.36 s, about 22 steps, later), which
# ends the player's pair; landing (by frame 90, run_input_test.sh) begins it again.
run --sample 6 --frames 52 --input "30 key-press Space"
expect contacts 4 "crates: in the air, the player's pair with the floor has ended"
run --sample 6 --frames 90 --input "30 key-press Space"
expect contacts 5 "crates: landed again, the player touches the floor again"
# Pyramid (sample 3, shared::pyramid(20)): unit boxes edge to edge, exactly. Row r (0 at
# the bottom) holds 20 - r boxes, each row-r+1 box centred over the seam of two row-r
# boxes. Touching: 20 boxes on the ground, 2 x (19 + 18 + ... + 1) = 380 boxes on two
# below, and (19 + 18 + ... + 1) = 190 side by side: 590.
run --sample 3 --frames 120
expect contacts 590 "pyramid: 20 on the ground + 380 on the row below + 190 side by side"

# --- The broadphase picture (docs/broadphase.md, "Levels by size"), as --report gives it.
#
# Pyramid at frame 2: all 210 boxes awake, in the moving grid, each 1 x 1 grown by at most
# a step's motion (a hair at this point). Level 0's cells are 1.25 times the smallest box:
# 1.25 (and a hair). All 210 fit in them, so level 0 holds them all.
run --sample 3 --frames 2
expect grid moving "pyramid at the start: the moving grid"
expect grid_boxes 210 "pyramid at the start: the 210 boxes move"
expect grid_level 0 "pyramid at the start: the boxes fill level 0"
expect grid_level_boxes 210 "pyramid at the start: all 210 boxes in level 0"
near grid_cell 1.25 0.01 "pyramid at the start: cells of 1.25 x the 1-unit boxes"
# Crates at frame 90: all five bodies have rested for more than half a second, so they
# sleep (docs/sleeping.md) and nothing is in the moving grid; the picture is the resting
# grid's: 3 static bodies + 5 sleeping ones. Smallest: the player, 44 tall, so level 0's
# cells are 55; the crates (56) go to level 1 (110). Levels 0 and 1 hold 5 of 8 boxes,
# less than 90%, so they stay apart. The walls (480 tall) go to level 4 (880), the floor
# (1040 wide) to level 5 (1760). The most boxes, 4 crates, are in level 1.
run --sample 6 --frames 90
expect grid resting "crates at rest: the resting grid"
expect grid_boxes 8 "crates at rest: 3 static bodies and 5 asleep"
expect grid_level 1 "crates at rest: the crates' level holds the most"
expect grid_cell 110.000 "crates at rest: level 1's cells are 2 x 1.25 x 44"
expect grid_level_boxes 4 "crates at rest: the 4 crates in level 1"

# --- On screen: crates at frame 90, debug drawing on (Tab at frame 2) and off.
#
# The pane is 1272 x 648 pixels at (4, 48) (the window is 1280 x 720, with a header of 48
# and a footer of 24 pixels and 4-pixel gaps). It shows x 0 to 1000 and y 250 to 540 with
# a margin of 50 all round (a twentieth of 1000): 1100 x 390, scaled by 1272 / 1100 to
# fit, centred. pixel_x and pixel_y map a world point to its pixel.
scale="1272 / 1100"
pixel_x() { awk -v x="$1" "BEGIN { s = $scale; printf \"%d\", x * s + (4 + 636 - 500 * s) + 0.5 }"; }
pixel_y() { awk -v y="$1" "BEGIN { s = $scale; printf \"%d\", y * s + (48 + 324 - 395 * s) + 0.5 }"; }
contact_colour=fafa78   # DebugPalette::contact
grid_colour=326e8c      # DebugPalette::gridCell
crate_colour=f0963c     # dynamic bodies
asleep_colour=845221    # dynamic bodies at 55%, asleep with debug drawing on
on="$out/crates-debug-on.bmp" off="$out/crates-debug-off.bmp"
rm -f "$on" "$off"
"$demo" --sample 6 --frames 90 --input "2 key-press Tab" --screenshot "$on" >/dev/null ||
  { echo "FAIL: jostle-demo could not save $on" >&2; failed=1; }
"$demo" --sample 6 --frames 90 --screenshot "$off" >/dev/null ||
  { echo "FAIL: jostle-demo could not save $off" >&2; failed=1; }

# Contacts: each of the five stands on the floor, so its contact point is at the middle
# of its bottom face, (x, 500): a 3 x 3 dot, and the normal drawn up into the body it
# pushes, 14 pixels long (each body is taller than 28 pixels). Below the pane's legend
# (whose word "contacts" is in the same colour), the colour is found only at those five
# places.
floor_y=$(pixel_y 500)
at_contacts=0
for x in 80 240 410 580 750; do
  px=$(pixel_x "$x")
  pixels "debug on: the dot at ($x, 500)" "$on" $contact_colour \
    $((px - 1)) $((floor_y - 1)) $((px + 1)) $((floor_y + 1)) 9
  pixels "debug on: the normal above ($x, 500), pointing up into the body" "$on" \
    $contact_colour "$px" $((floor_y - 12)) "$px" $((floor_y - 2)) 11
  pixels "debug on: the normal goes up, not down into the floor" "$on" $contact_colour \
    "$px" $((floor_y + 2)) "$px" $((floor_y + 14)) 0
  got=$(count "$on" $contact_colour $((px - 4)) $((floor_y - 20)) $((px + 4)) $((floor_y + 4)))
  at_contacts=$((at_contacts + ${got//error/0}))
done
pixels "debug on: contact marks at the five contacts and nowhere else" "$on" $contact_colour \
  4 100 1275 695 "$at_contacts"
pixels "debug off: no contact marks anywhere" "$off" $contact_colour 4 48 1275 695 0

# Grid: the library draws the outline of each cell that holds a box (World::debugDraw),
# under the bodies. A box is filed in the cell of its level that holds its min corner:
# the 0.5 kg crate (min corner (212, 442), level 1, cells of 110) in the cell from x 110
# to 220 and y 440 to 550. So the column of x 110 is that cell's edge from y 440 down to
# the floor's top at 500 (the floor is drawn over the rest), and its row of y 440 runs
# from x 110 to 220. Above every body, between y 300 and 400, no box and so no cell.
top=$(pixel_y 300) bottom=$(pixel_y 400)
column=$(pixel_x 110) edge_top=$(pixel_y 445) edge_bottom=$(pixel_y 495)
row=$(pixel_y 440) row_left=$(pixel_x 115) row_right=$(pixel_x 205)
pixels "debug on: the cell's left edge at x 110, from y 445 to 495" "$on" $grid_colour \
  "$column" "$edge_top" "$column" "$edge_bottom" $((edge_bottom - edge_top + 1))
pixels "debug on: the cell's top edge at y 440, from x 115 to 205" "$on" $grid_colour \
  "$row_left" "$row" "$row_right" "$row" $((row_right - row_left + 1))
pixels "debug on: no cell above the bodies at x 110" "$on" $grid_colour \
  "$column" "$top" "$column" "$bottom" 0
pixels "debug off: no cell edge at x 110" "$off" $grid_colour \
  "$column" "$edge_top" "$column" "$edge_bottom" 0

# Sleeping bodies: the 0.5 kg crate (x 212 to 268, y 442 to 498) is asleep by frame 90.
# Inside it, left of its normal and above its bottom edge, from (220, 450) to (232, 490):
# dimmed with debug drawing on, its usual colour with it off.
x0=$(pixel_x 220) y0=$(pixel_y 450) x1=$(pixel_x 232) y1=$(pixel_y 490)
area=$(((x1 - x0 + 1) * (y1 - y0 + 1)))
pixels "debug on: the sleeping crate dimmed" "$on" $asleep_colour "$x0" "$y0" "$x1" "$y1" $area
pixels "debug off: the crate in its usual colour" "$off" $crate_colour \
  "$x0" "$y0" "$x1" "$y1" $area
exit "$failed"
