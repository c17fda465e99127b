#!/usr/bin/env bash
# Sets everything up, builds, and runs the tutorial's scene with the jostle program.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
./build/jostle run examples/scenes/tutorial.json --steps 600
