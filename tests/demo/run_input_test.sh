#!/usr/bin/env bash
# Drives jostle-demo's keys and mouse with --input scripts and checks what --report prints
# at exit. It runs headless on SDL's offscreen video driver (no X server needed); with
# --frames every frame is one 1/60 s step, so the numbers are the same every run.
#
#   run_input_test.sh DEMO
#
# Exits 77 (the test's SKIP_RETURN_CODE) only if SDL cannot open an offscreen window.
set -uo pipefail
demo=$1

# shellcheck source-path=SCRIPTDIR source=report_checks.sh
. "$(dirname "$0")/report_checks.sh"
offscreen

# --- Platformer (sample 2): run speed 260 px/s, jump 4 tiles (128 px) high. The player
# (22 x 40 px) starts at (100, 480) and settles on the floor (top y 512) at y 492.
run --sample 2 --frames 30
expect sample platformer "sample 2 at start"
initial_bodies=$(value bodies)
expect player_x 100.000 "the player starts at x 100"
near player_y 492 0.01 "the player stands on the floor (512 - 20)"

# Right held from frame 30 to 59: 30 steps of 1/60 s at 260 px/s = 130 px.
run --sample 2 --frames 90 --input "30 key-down Right; 60 key-up Right"
near player_x 230 0.01 "Right held 0.5 s runs 260 px/s x 0.5 s"
expect player_vx 0.000 "releasing Right stops the run"
near player_y 492 0.01 "running stays on the floor"

# Left held for 0.5 s: up the two low steps in the corner (12 px each, x 32 to 80) without
# a jump (stepUp), to the wall (x 32): the player on the upper step's top (488 - 20).
run --sample 2 --frames 70 --input "30 key-down Left; 60 key-up Left"
near player_x 43 0.01 "Left held runs up the low steps to the wall (32 + 11)"
near player_y 468 0.01 "walked up onto the upper step (512 - 24 - 20)"
expect player_floor 1 "standing on it"

# Space on the floor while running right for 15 steps (65 px): the player rises (take-off
# speed sqrt(2 g h) = 674 px/s up), and lands on the jump-through platform at (160, 400),
# whose top (395) is 117 px above the floor, so stands at y 395 - 20 = 375. Down + space
# there drops through it, back to the floor (492).
jump="30 key-down Right; 30 key-press Space; 45 key-up Right; 100 key-down Down"
jump+="; 100 key-press Space; 101 key-up Down"
run --sample 2 --frames 40 --input "$jump"
below player_y 492 "space on the floor jumps: y decreases"
below player_vy 0 "space on the floor jumps: moving up"
run --sample 2 --frames 99 --input "$jump"
near player_x 165 0.01 "15 steps right at 260 px/s before the jump: 100 + 65"
near player_y 375 0.01 "the jump lands on the jump-through platform (395 - 20)"
expect player_floor 1 "standing on the jump-through platform"
run --sample 2 --frames 130 --input "$jump"
near player_y 492 0.01 "Down + space drops through the platform, back to the floor"

# --- The example level (sample 9): examples/levels/level.tmj, drawn in Tiled, read by
# jostle::parseTiled. Tiles are 16 px; the floor is row 14 (top y 224). The character
# (10 x 14 px) starts on the map's "spawn" point (40, 200) and falls to stand at y 224 - 7.
run --sample 9 --frames 30
expect sample level "sample 9 is the Tiled level"
level_bodies=$(value bodies)
expect player_x 40.000 "the character starts at the spawn point's x"
near player_y 217 0.01 "and stands on the floor (224 - 7)"
expect coins 0 "no coin yet"
# Right held 0.5 s at 120 px/s: 60 px along the flat floor.
run --sample 9 --frames 90 --input "30 key-down Right; 60 key-up Right"
near player_x 100 0.01 "Right held 0.5 s runs 120 px/s x 0.5 s"
# Right held 2.5 s: up the ramp of column 8 onto the block of row 13 (top y 208), through
# the first coin (a sensor from x 172 to 180, y 204 to 212, the map's "coin" object),
# which is collected and destroyed, and down the block's far ramp to the floor.
run --sample 9 --frames 200 --input "30 key-down Right; 180 key-up Right"
expect coins 1 "walking over the block collects its coin"
expect bodies $((level_bodies - 1)) "the coin's body is gone"
near player_y 217 0.01 "back on the floor beyond the block"
expect player_floor 1 "standing"

# Right-click drops a box (the centre of the pane is empty space in the level): one body
# more per click. R rebuilds the sample: the initial count, the player back at x 100.
run --sample 2 --frames 20 --input "10 mouse-click right 640 372"
expect bodies $((initial_bodies + 1)) "right-click drops one box"
run --sample 2 --frames 20 --input "10 mouse-click right 640 372; 12 mouse-click right 700 372; 14 key-down Right; 18 key-press r; 18 key-up Right"
expect bodies "$initial_bodies" "R resets the sample: the initial body count"
expect player_x 100.000 "R resets the sample: the player back at its start"

# Tab toggles debug drawing; D does not in the platformer (there it runs right).
run --sample 2 --frames 10 --input "3 key-press Tab"
expect debug 1 "Tab turns debug drawing on"
run --sample 2 --frames 10 --input "3 key-press Tab; 5 key-press Tab"
expect debug 0 "Tab again turns it off"
run --sample 2 --frames 10 --input "3 key-down d"
expect debug 0 "D does not toggle debug in the platformer"
near player_x 134.667 0.01 "D held runs right: 8 steps of 260/60 px = 34.67"

# --- Tutorial (sample 1): D toggles debug, S slow motion.
run --sample 1 --frames 10 --input "3 key-press d; 5 key-press s"
expect sample tutorial "sample 1"
expect debug 1 "D turns debug drawing on in the tutorial"
expect slow 1 "S turns slow motion on"

# The debug key is the same everywhere: Tab in every sample; D as well in the samples
# where it steers nothing (all but 2, 6 and 7, where it runs right).
for sample in 1 2 3 4 5 6 7; do
  run --sample "$sample" --frames 6 --input "3 key-press Tab"
  expect debug 1 "Tab turns debug drawing on in sample $sample"
  run --sample "$sample" --frames 6 --input "3 key-press d"
  case $sample in
    2 | 6 | 7) expect debug 0 "D runs, and leaves debug drawing off, in sample $sample" ;;
    *) expect debug 1 "D turns debug drawing on in sample $sample" ;;
  esac
done

# --- Crates (sample 6): run speed 220 px/s, jump 90 px high in 0.36 s. The player
# (24 x 44 px) starts at (80, 470) and settles on the floor (top y 500) at y 478.
# P pauses, N steps once: Right held from frame 10, P at 30 (20 steps: 80 + 20 x 220/60
# = 153.33); no motion while paused, then N adds one step (+3.67 = 157).
pause="10 key-down Right; 30 key-press p; 60 key-press n"
run --sample 6 --frames 50 --input "$pause"
expect paused 1 "P pauses"
near player_x 153.333 0.01 "20 steps of Right before the pause"
run --sample 6 --frames 59 --input "$pause"
near player_x 153.333 0.01 "paused: the player does not move in 9 more frames"
run --sample 6 --frames 90 --input "$pause"
near player_x 157 0.01 "N steps once (220/60 px) and stays paused"
expect paused 1 "still paused after N"
run --sample 6 --frames 60 --input "10 key-press p; 20 key-press p; 20 key-down Right"
expect paused 0 "P again resumes"
# 41 steps x 220/60 = 150.3 px; the player was still settling on the floor when paused.
near player_x 230.3 1 "running again after resuming: 41 steps"

# Space on the floor: the player rises (take-off speed sqrt(2 g h) = 500 px/s, apex 90 px
# up at 0.36 s, about 22 steps) and lands back on the floor by frame 90.
run --sample 6 --frames 40 --input "30 key-press Space"
below player_y 478 "crates: space jumps, y decreases"
run --sample 6 --frames 52 --input "30 key-press Space"
near player_y $((478 - 90)) 8 "crates: near the apex 90 px up after 0.36 s"
run --sample 6 --frames 90 --input "30 key-press Space"
near player_y 478 0.01 "crates: the jump lands back on the floor"
expect player_floor 1 "crates: standing again"

# Left-drag: the view maps world (x, y) to pixels (1.15636 x + 61.82, 1.15636 y - 84.76),
# so the player at (80, 478) is at pixel (154, 468); dragging it to pixel (154, 300) pulls
# it towards world y (300 + 84.76) / 1.15636 = 332.7, against gravity.
run --sample 6 --frames 60 --input "20 mouse-down left 154 468; 21 mouse-move 154 300"
expect dragging 1 "left-down on the player holds it"
near player_y 332.7 5 "the held player follows the cursor up to y 332.7"
near player_x 80 1 "and stays under it"
run --sample 6 --frames 90 --input "20 mouse-down left 154 468; 21 mouse-move 154 300; 60 mouse-up left 154 300"
expect dragging 0 "releasing the button lets go"
near player_y 478 0.01 "let go, the player falls back to the floor"

# --- Slopes (sample 7): a character (14 x 24 px, snapDown 6) walks at 160 px/s from
# x 260 on the floor (top y 480) over the hill: a 2:1 ramp up from (310, 480) to
# (390, 440), a flat top to x 470, a 2:1 ramp down to (550, 480). On a ramp it stands on
# the corner nearest the top: y = surface there - 12. Right held from frame 30.
run --sample 7 --frames 60 --input "30 key-down Right"
near player_vx 160 0.01 "the character walks up the hill at its walk speed"
near player_y "$(awk -v x="$(value player_x)" 'BEGIN { print 480 - (x + 7 - 310) / 2 - 12 }')" 0.05 \
  "its right corner on the ramp up"
expect player_floor 1 "on the ground going up"
run --sample 7 --frames 90 --input "30 key-down Right"
near player_y 428 0.01 "on the flat top (440 - 12), not flown off the crest"
expect player_floor 1 "on the ground at the top"
run --sample 7 --frames 120 --input "30 key-down Right"
near player_vx 160 0.01 "and down the other side at its walk speed"
near player_y "$(awk -v x="$(value player_x)" 'BEGIN { print 440 + (x - 7 - 470) / 2 - 12 }')" 0.05 \
  "its left corner on the ramp down: snapped to it"
expect player_floor 1 "on the ground going down"

# --- Rollback (sample 8): each peer hears the other's keys 6 frames late and rolls back when
# they are not what it guessed (the last heard, with no jump). Peer B hears yours: Right
# down, Right up, Left down, Left up and two jumps are 6 rollbacks. Peer A hears the
# script's (left below phase 110 of 240, right from 120 to 229, a jump at 45 every 90): by
# frame 393 it changed at frames 0, 110, 120, 230, 240, 350, 360 and jumped at 45, 135,
# 225, 315: 11 rollbacks. The states of the last frame both know agree.
run --sample 8 --frames 400 --input "30 key-down Right; 100 key-up Right; 120 key-press Space; 150 key-down Left; 250 key-up Left; 260 key-press Space"
expect sample rollback "sample 8"
expect confirmed_frame 392 "the last frame both peers know is 400 - 6 - 2"
expect peers_agree 1 "both peers' confirmed states are the same, bit for bit"
expect rollbacks_a 11 "peer A rolled back for each change of the script's keys"
expect rollbacks_b 6 "peer B rolled back for each change of yours"

# --- Keys 1 to 8 switch samples.
names=(tutorial platformer pyramid rain bullets crates slopes rollback)
for key in 1 2 3 4 5 6 7 8; do
  run --sample 3 --frames 3 --input "2 key-press $key"
  expect sample "${names[key - 1]}" "key $key"
done

# A mistake in the script is an error, not ignored.
if SDL_VIDEODRIVER=offscreen "$demo" --frames 2 --input "1 key-prss x" 2>/dev/null; then
  echo "FAIL: a misspelt action was accepted" >&2
  failed=1
fi
exit $failed
