#!/usr/bin/env bash
# Measures each scene family at several sizes in jostle, Box2D and Chipmunk, and plots
# ms per step against body count: docs/benchmarks.png (data in docs/benchmarks-series.csv).
# Takes several minutes.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh gnuplot-nox
csv=docs/benchmarks-series.csv
scripts/bench.sh --series pyramid,rain,gas,tilemap --max-seconds 10 --csv "$csv" "$@" >/dev/null
scripts/plot-bench.gp "$csv" docs/benchmarks.png
echo "plot-bench: wrote docs/benchmarks.png from $csv"
