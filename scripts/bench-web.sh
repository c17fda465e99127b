#!/usr/bin/env bash
# The web benchmark (docs/benchmarks.md#the-web): jostle's npm package beside matter-js,
# Rapier (plain and SIMD) and planck in one Node process, on the scenes of
# shared/scenes.hpp written as scene files. The peers come from the npm registry into a
# scratch directory (build-bench-web/peers), at the versions named here; they are the
# benchmark's, never the package's dependencies. Arguments go to bench/web/bench.mjs
# (--runs 3, --scene pyramid_50,rain_2k, --engine jostle,rapier, --markdown).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/web.sh --build-only >&2                      # build-web/npm/jostle
mkdir -p build-bench-web/scenes build-bench-web/peers
scripts/bench.sh web-scenes build-bench-web/scenes >/dev/null
peers=(matter-js@0.20.0 @dimforge/rapier2d-compat@0.19.3 @dimforge/rapier2d-simd-compat@0.19.3 planck@1.5.0)
[ -f build-bench-web/peers/package.json ] || echo '{"private": true}' > build-bench-web/peers/package.json
npm install --prefix build-bench-web/peers --no-audit --no-fund --silent "${peers[@]}"
echo "node $(node --version); peers: ${peers[*]}"
exec node bench/web/bench.mjs --package build-web/npm/jostle --peers build-bench-web/peers/node_modules \
  --scenes build-bench-web/scenes "$@"
