#!/usr/bin/env bash
# Runs jostle-demo under a virtual X server (xvfb-run, Debian's xvfb) for each sample,
# 120 frames each with --screenshot, with debug drawing off and on, and checks that it
# exits with 0 and that the screenshot exists and is not a single colour.
#
#   run_demo_test.sh DEMO CHECKER OUT_DIR
#
# Exits 77 (the test's SKIP_RETURN_CODE) when xvfb-run is not installed.
set -uo pipefail

if [ "${1:-}" = "--under-xvfb" ]; then
  shift
  demo=$1 checker=$2 out=$3
  failed=0
  for sample in 1 2 3 4 5 6 7 8 9; do
    # Plain, and with debug drawing on from frame 2 (its blended tints and many marks
    # drawn by the display's own renderer).
    for debug in "" debug; do
      shot="$out/sample-$sample${debug:+-$debug}.bmp"
      input=${debug:+2 key-press Tab}
      rm -f "$shot"
      if ! "$demo" --sample "$sample" --frames 120 --screenshot "$shot" \
        ${input:+--input "$input"}; then
        echo "sample $sample ${debug}: jostle-demo failed" >&2
        failed=1
        continue
      fi
      if [ ! -f "$shot" ]; then
        echo "sample $sample ${debug}: no screenshot at $shot" >&2
        failed=1
        continue
      fi
      "$checker" "$shot" || failed=1
    done
  done
  exit $failed
fi

if ! command -v xvfb-run >/dev/null 2>&1; then
  echo "skipped: xvfb-run is not installed (Debian package xvfb; scripts/setup.sh installs it)"
  exit 77
fi
mkdir -p "$3"
# One X server for all fourteen runs: starting one per run costs about a second each. The
# screen is as large as the demo's window.
exec xvfb-run -a -s "-screen 0 1280x720x24" "$0" --under-xvfb "$@"
