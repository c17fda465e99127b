#!/usr/bin/env bash
# Checks that jostle-demo's samples are laid out so that what moves has room to: the
# platformer's lift rises and sinks through a shaft that no wall or ledge crosses.
#
#   run_layout_test.sh DEMO
#
# Runs headless on SDL's offscreen video driver, as run_input_test.sh does; exits 77 (the
# test's SKIP_RETURN_CODE) only if SDL cannot open an offscreen window.
set -uo pipefail
demo=$1
export SDL_VIDEODRIVER=offscreen

if ! "$demo" --frames 1 >/dev/null 2>&1; then
  echo "skipped: jostle-demo cannot open a window with SDL_VIDEODRIVER=offscreen"
  exit 77
fi

# shellcheck source-path=SCRIPTDIR source=report_checks.sh
. "$(dirname "$0")/report_checks.sh"

# --- The platformer's lift (sample 2). A kinematic body passes through static ones, so
# only the level's layout keeps its path clear; --report counts the steps after which a
# kinematic body overlapped a static one by more than touching. The lift goes from
# y 520 up to 230 and back at 90 px/s, 1.5 px a step: 194 steps each way, so 400 frames
# hold a whole round trip, past the steps, the ledge of row 7 and the pit's sides.
run --sample 2 --frames 400
expect kinematic_in_static 0 "platformer: the lift's shaft is clear all the way up and down"

exit "$failed"
