// What a call through the npm package's JavaScript costs (issue 33: a few hundred
// nanoseconds at most; reading 10,000 positions one call): medians of 7 runs of a loop
// each, in nanoseconds a call.
//   node bench/web/calls.mjs <package dir>     (build-web/npm/jostle, scripts/npm-pack.sh)
import path from "node:path";
import {pathToFileURL} from "node:url";

const packageDir = process.argv[2] ?? "build-web/npm/jostle";
const {load} = await import(pathToFileURL(path.resolve(packageDir, "jostle.mjs")).href);
const jostle = await load();
const world = jostle.createWorld({gravity: [0, 800]});
world.createBody({type: "static", x: 0, y: 0, hw: 1000, hh: 1});
const hero = world.createBody({x: 0, y: -20, hw: 1, hh: 1, character: true});
for (let i = 0; i < 9999; i++) world.createBody({x: (i % 100) * 3, y: -10 - (i / 100 | 0) * 3, hw: 1, hh: 1});
const positions = new Float32Array(2 * world.bodyCount);

/// Nanoseconds a call of `f`, the median of 7 runs of `count` calls.
function time(count, f) {
  for (let i = 0; i < count; i++) f(i);
  const runs = [];
  for (let run = 0; run < 7; run++) {
    const start = process.hrtime.bigint();
    for (let i = 0; i < count; i++) f(i);
    runs.push(Number(process.hrtime.bigint() - start) / count);
  }
  return runs.sort((a, b) => a - b)[3];
}

let sink = 0;
const rows = [
  ["hero.walkSpeed = v", time(1e6, (i) => { hero.walkSpeed = i & 127; })],
  ["hero.position (read)", time(1e6, () => { sink += hero.position.x; })],
  ["hero.setVelocity(vx, vy)", time(1e6, (i) => hero.setVelocity(i & 7, 0))],
  ["world.readPositions (10,000 bodies)", time(1000, () => { sink += world.readPositions(positions); })],
];
for (const [what, ns] of rows) console.log(`${what.padEnd(38)} ${ns.toFixed(0).padStart(8)} ns`);
if (sink === -1) console.log(sink);
