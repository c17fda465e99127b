// What snapshots cost in WebAssembly (Node) beside the native build, on
// the pile of bench/snapshots.cpp (1,000 boxes on a floor, 40 a row, friction 0.6, sleeping
// off, stepped a second): the median of `runs` timings of snapshot(into), restore(),
// stateHash() and a step, through the npm package as a game calls them, then the native
// program's figures for the same pile. Not a test: docs/benchmarks.md#snapshots has them.
//   node bench/web/snapshots.mjs <package dir> <jostle-bench-snapshots> [runs]
import {execFileSync} from "node:child_process";
import path from "node:path";
import {pathToFileURL} from "node:url";

function medianMicroseconds(runs, work) {
  const times = [];
  for (let run = 0; run < runs; run++) {
    const start = process.hrtime.bigint();
    work();
    times.push(Number(process.hrtime.bigint() - start) / 1000);
  }
  times.sort((a, b) => a - b);
  return times[Math.floor(times.length / 2)];
}

async function main() {
  const [packageDir, nativeTool, runsText = "50"] = process.argv.slice(2);
  const runs = Number(runsText);
  const {load} = await import(pathToFileURL(path.resolve(packageDir, "jostle.mjs")).href);
  const jostle = await load();
  const bodies = [{type: "static", x: 0, y: 10, hw: 2000, hh: 10}];
  for (let i = 0; i < 1000; i++)
    bodies.push({x: -500 + 10 * (i % 40), y: -5 - 10 * Math.floor(i / 40), hw: 5, hh: 5, friction: 0.6});
  const world = jostle.createWorld({gravity: [0, 600], sleeping: false, bodies});
  for (let step = 0; step < 60; step++) world.step(1 / 60);
  const saved = world.snapshot(), room = new Uint8Array(saved.length);
  const web = {
    bytes: saved.length,
    // Into a buffer of the caller's, as the native program's snapshot(span).
    save: medianMicroseconds(runs, () => world.snapshot(room)),
    restore: medianMicroseconds(runs, () => world.restore(saved)),
    hash: medianMicroseconds(runs, () => world.stateHash()),
    step: medianMicroseconds(runs, () => { world.restore(saved); world.step(1 / 60); }) -
          medianMicroseconds(runs, () => world.restore(saved)),
  };
  const native = execFileSync(nativeTool, ["--bodies", "1000", "--runs", String(runs)], {encoding: "utf8"})
    .split("\n").find((line) => line.startsWith("| 1000 |")).split("|").map((cell) => cell.trim());
  const [, , , bytes, , save, restore, hash, step] = native;
  console.log("| 1,000 boxes | bytes | save µs | restore µs | stateHash µs | step µs |");
  console.log("|---|---:|---:|---:|---:|---:|");
  console.log(`| native | ${bytes} | ${save} | ${restore} | ${hash} | ${step} |`);
  console.log(`| WebAssembly (Node ${process.versions.node}) | ${web.bytes} | ${web.save.toFixed(1)} | ` +
              `${web.restore.toFixed(1)} | ${web.hash.toFixed(1)} | ${web.step.toFixed(1)} |`);
  console.log(`| WebAssembly / native | | ${(web.save / save).toFixed(2)} | ${(web.restore / restore).toFixed(2)} | ` +
              `${(web.hash / hash).toFixed(2)} | ${(web.step / step).toFixed(2)} |`);
  world.destroy();
}

main().catch((error) => {
  console.log(error.stack);
  process.exit(1);
});
