#!/usr/bin/env bash
# Runs the LÖVE example (bindings/lua/example) for 3 simulated seconds under a virtual X
# server and checks that it started, loaded jostle.so and saw every box land, and that its
# scripted player (a character) walked at exactly 150 and jumped as high as worked out by
# hand (106.78); and that with --debug, world:debugDraw drew one shape a body.
#
#   run_love_example.sh EXAMPLE_DIR MODULE_DIR
#
# MODULE_DIR holds the LuaJIT build of jostle.so (LÖVE 11 runs LuaJIT). Exits 77 (the
# test's SKIP_RETURN_CODE) where love or xvfb-run is not installed.
set -uo pipefail

example=$1 module_dir=$2

for program in love xvfb-run; do
  if ! command -v "$program" >/dev/null 2>&1; then
    echo "skipped: $program is not installed (Debian packages love and xvfb)"
    exit 77
  fi
done

# The module through LUA_CPATH alone, so that a jostle.so left next to main.lua or
# installed elsewhere does not stand in for the one just built. No sound card is needed
# (the example turns audio off); the dummy driver keeps SDL quiet if it looks anyway.
failed=0
for model in physical classic; do
  output=$(LUA_CPATH="$module_dir/?.so" SDL_AUDIODRIVER=dummy \
    timeout 25 xvfb-run -a -s "-screen 0 1024x768x24" love "$example" --seconds 3 --model $model 2>&1)
  status=$?
  echo "$output"
  if [ $status -ne 0 ]; then
    echo "$model: love exited with status $status" >&2
    failed=1
    continue
  fi
  # "... 9 of 9 boxes landed ...": every box of the tutorial's scene touched something.
  if ! grep -Eq "jostle example: 3\.00 s simulated .* $model model, .* ([0-9]+) of \1 boxes landed" <<<"$output"; then
    echo "$model: the example's summary line is missing or not every box landed" >&2
    failed=1
  fi
  if ! grep -q "jostle example: the player walked at 150.0 to 150.0 and jumped 106.78 high" <<<"$output"; then
    echo "$model: the player's line is missing, or it did not walk at 150 or jump 106.78" >&2
    failed=1
  fi
done

# Debug drawing (world:debugDraw through LÖVE's functions): every body one shape, the
# world's bodies all in view (the example's walls and floor frame it).
output=$(LUA_CPATH="$module_dir/?.so" SDL_AUDIODRIVER=dummy \
  timeout 25 xvfb-run -a -s "-screen 0 1024x768x24" love "$example" --seconds 1 --debug 2>&1)
echo "$output"
if ! grep -Eq "jostle example: debug drawing drew ([0-9]+) shapes for \1 bodies" <<<"$output"; then
  echo "debug drawing: the line is missing or it did not draw one shape a body" >&2
  failed=1
fi
exit $failed
