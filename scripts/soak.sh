#!/usr/bin/env bash
# The soak test: a busy world for an hour of simulated time (216,000 steps), checking
# that memory stays flat and that the invariants hold (tests/soak/soak.cpp). Sets up,
# builds the Release build in build/ (scripts/build.sh), and runs jostle-soak; about a
# quarter of an hour of wall time. Options go to jostle-soak: --minutes N, --seed S.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
build/tests/soak/jostle-soak --minutes 60 "$@"
