// The web benchmark (issue 33): the scenes of jostle-web-scenes in jostle's npm package,
// matter-js, Rapier (its plain and SIMD builds) and planck, in one Node process, the
// engines alternated run by run after a warm-up run. Each engine builds the scene file's
// bodies as itself (non-rotating, sleeping off, 60 Hz, its default iterations), steps it,
// and gets the milliseconds a step (median of the runs), the drift of a pyramid's top box
// (how far it moved from where it was built, resting) and the largest overlap of two boxes
// at the end, measured here alike for every engine from its boxes' centres and the file's
// half extents.
// Not a test: scripts/bench-web.sh installs the peers and runs it; docs/benchmarks.md
// records it.
//   node bench.mjs --package <dir> --peers <node_modules dir> --scenes <dir> [--runs 3]
//                  [--scene name,...] [--engine name,...] [--markdown]
import {readFile, readdir} from "node:fs/promises";
import {createRequire} from "node:module";
import path from "node:path";
import {pathToFileURL} from "node:url";

const options = {runs: 3, scene: null, engine: null, markdown: false};
for (let i = 2; i < process.argv.length; i++) {
  const arg = process.argv[i];
  if (arg === "--markdown") options.markdown = true;
  else options[arg.replace(/^--/, "")] = process.argv[++i];
}
const require = createRequire(path.resolve(options.peers, "..", "package.json"));

// Steps each scene runs: enough for rain to land and a pyramid to show any drift.
const kSteps = {pyramid_20: 600, pyramid_50: 300, many_pyramids_10: 300, rain_2k: 240, gas_2k: 240,
                tilemap_1k: 240, floor_5k: 120};
const kDt = 1 / 60;

// --- The engines: each builds a scene's bodies and steps them ------------------------------

/// jostle's npm package, from the scene file's text itself.
async function jostleEngine() {
  const {load} = await import(pathToFileURL(path.resolve(options.package, "jostle.mjs")).href);
  const jostle = await load();
  return {
    name: "jostle",
    settings: "physical model, 4 velocity and 3 position iterations, no skin",
    build(scene, text) {
      const world = jostle.createWorld(text);
      const out = new Float32Array(2 * scene.bodies.length);
      return {step: () => world.step(kDt), centres: () => (world.readPositions(out), out), free: () => world.destroy()};
    },
  };
}

/// matter-js works in pixels, with gravity in pixels a millisecond squared: a unit is
/// kScale pixels (its slop, 0.05 px, is made for bodies tens of pixels wide).
async function matterEngine() {
  const Matter = require("matter-js");
  const kScale = 40;
  return {
    name: "matter-js",
    settings: `${kScale} px a unit, 6 position and 4 velocity iterations, slop 0.05 px, frictionAir 0`,
    build(scene) {
      const engine = Matter.Engine.create({enableSleeping: false});
      engine.gravity.x = 0;
      engine.gravity.y = 1;
      engine.gravity.scale = scene.gravity[1] * kScale * 1e-6;
      const bodies = scene.bodies.map((b) => {
        const body = Matter.Bodies.rectangle(b.x * kScale, b.y * kScale, 2 * b.hw * kScale, 2 * b.hh * kScale,
          {isStatic: b.type === "static", friction: b.friction ?? 0.5, restitution: b.bounce ?? 0,
           frictionAir: 0, frictionStatic: 0.5, inertia: Infinity});
        if (b.vx || b.vy) Matter.Body.setVelocity(body, {x: (b.vx ?? 0) * kScale * kDt, y: (b.vy ?? 0) * kScale * kDt});
        return body;
      });
      Matter.Composite.add(engine.world, bodies);
      const out = new Float32Array(2 * bodies.length);
      return {
        step: () => Matter.Engine.update(engine, 1000 * kDt),
        centres() {
          bodies.forEach((body, i) => { out[2 * i] = body.position.x / kScale; out[2 * i + 1] = body.position.y / kScale; });
          return out;
        },
        free: () => Matter.Engine.clear(engine),
      };
    },
  };
}

/// Rapier, its plain or SIMD build (the -compat packages, whose wasm is inlined).
async function rapierEngine(name, module) {
  const RAPIER = (await import(pathToFileURL(require.resolve(module)).href)).default;
  await RAPIER.init();
  return {
    name,
    settings: "4 solver iterations, 1 stabilization iteration, contact skin 0, min friction and max restitution",
    build(scene) {
      const world = new RAPIER.World({x: scene.gravity[0], y: scene.gravity[1]});
      world.timestep = kDt;
      const bodies = scene.bodies.map((b) => {
        const desc = (b.type === "static" ? RAPIER.RigidBodyDesc.fixed() : RAPIER.RigidBodyDesc.dynamic())
          .setTranslation(b.x ?? 0, b.y ?? 0).lockRotations().setCanSleep(false)
          .setLinvel(b.vx ?? 0, b.vy ?? 0);
        const body = world.createRigidBody(desc);
        const collider = RAPIER.ColliderDesc.cuboid(b.hw, b.hh).setFriction(b.friction ?? 0.5)
          .setRestitution(b.bounce ?? 0)
          .setFrictionCombineRule(RAPIER.CoefficientCombineRule.Min)
          .setRestitutionCombineRule(RAPIER.CoefficientCombineRule.Max);
        if (b.mass) collider.setMass(b.mass);
        else collider.setDensity(b.density ?? 1);
        world.createCollider(collider, body);
        return body;
      });
      const out = new Float32Array(2 * bodies.length);
      return {
        step: () => world.step(),
        centres() {
          bodies.forEach((body, i) => { const t = body.translation(); out[2 * i] = t.x; out[2 * i + 1] = t.y; });
          return out;
        },
        free: () => world.free(),
      };
    },
  };
}

/// planck, Box2D's JavaScript port.
async function planckEngine() {
  const planck = require("planck");
  return {
    name: "planck",
    settings: "8 velocity and 3 position iterations, polygon skin 0.01 units (Box2D's)",
    build(scene) {
      const world = new planck.World({gravity: planck.Vec2(scene.gravity[0], scene.gravity[1])});
      const bodies = scene.bodies.map((b) => {
        const body = world.createBody({type: b.type === "static" ? "static" : "dynamic",
                                       position: planck.Vec2(b.x ?? 0, b.y ?? 0), fixedRotation: true,
                                       allowSleep: false, linearVelocity: planck.Vec2(b.vx ?? 0, b.vy ?? 0)});
        body.createFixture({shape: new planck.Box(b.hw, b.hh), friction: b.friction ?? 0.5,
                            restitution: b.bounce ?? 0,
                            density: b.mass ? b.mass / (4 * b.hw * b.hh) : (b.density ?? 1)});
        return body;
      });
      const out = new Float32Array(2 * bodies.length);
      return {
        step: () => world.step(kDt),
        centres() {
          bodies.forEach((body, i) => { const p = body.getPosition(); out[2 * i] = p.x; out[2 * i + 1] = p.y; });
          return out;
        },
        free: () => {},
      };
    },
  };
}

// --- Quality, measured alike for every engine -------------------------------------------

/// The largest overlap of two boxes: the smaller of the two axes' overlaps, over every
/// pair, found by a sweep along x.
function largestOverlap(scene, centres) {
  const n = scene.bodies.length, order = Array.from({length: n}, (_, i) => i);
  const minX = (i) => centres[2 * i] - scene.bodies[i].hw;
  order.sort((a, b) => minX(a) - minX(b));
  let largest = 0;
  for (let k = 0; k < n; k++) {
    const i = order[k], bi = scene.bodies[i], maxX = centres[2 * i] + bi.hw;
    for (let l = k + 1; l < n; l++) {
      const j = order[l];
      if (minX(j) >= maxX) break;
      const bj = scene.bodies[j];
      if (bi.type === "static" && bj.type === "static") continue;
      const ox = Math.min(maxX, centres[2 * j] + bj.hw) - Math.max(minX(i), minX(j));
      const oy = Math.min(centres[2 * i + 1] + bi.hh, centres[2 * j + 1] + bj.hh) -
                 Math.max(centres[2 * i + 1] - bi.hh, centres[2 * j + 1] - bj.hh);
      if (ox > 0 && oy > 0) largest = Math.max(largest, Math.min(ox, oy));
    }
  }
  return largest;
}

/// How far the box with id "top" moved, or null in a scene without one.
function topDrift(scene, centres) {
  const i = scene.bodies.findIndex((b) => b.id === "top");
  if (i < 0) return null;
  return Math.hypot(centres[2 * i] - scene.bodies[i].x, centres[2 * i + 1] - scene.bodies[i].y);
}

// --- The runs ------------------------------------------------------------------------------

const engines = [await jostleEngine(), await matterEngine(),
                 await rapierEngine("rapier", "@dimforge/rapier2d-compat"),
                 await rapierEngine("rapier-simd", "@dimforge/rapier2d-simd-compat"),
                 await planckEngine()]
  .filter((engine) => options.engine === null || options.engine.split(",").includes(engine.name));
const names = (await readdir(options.scenes)).filter((f) => f.endsWith(".json")).map((f) => f.slice(0, -5))
  .filter((name) => name in kSteps && (options.scene === null || options.scene.split(",").includes(name)))
  .sort((a, b) => Object.keys(kSteps).indexOf(a) - Object.keys(kSteps).indexOf(b));

const rows = [];
for (const name of names) {
  const text = await readFile(path.join(options.scenes, `${name}.json`), "utf8");
  const scene = JSON.parse(text);
  scene.bodies.forEach((b) => { b.x ??= 0; b.y ??= 0; b.type ??= "dynamic"; });
  const results = new Map(engines.map((engine) => [engine.name, {times: [], drift: 0, overlap: 0}]));
  // Run -1 warms up, untimed: a wasm engine's first steps run its baseline code while the
  // optimising compiler works in the background, as they would only in a game's first second.
  for (let run = -1; run < Number(options.runs); run++)
    for (const engine of engines) { // alternated: each run has every engine once
      const world = engine.build(scene, text);
      const start = process.hrtime.bigint();
      for (let step = 0; step < kSteps[name]; step++) world.step();
      const ms = Number(process.hrtime.bigint() - start) / 1e6 / kSteps[name];
      const result = results.get(engine.name), centres = world.centres();
      if (run >= 0) result.times.push(ms);
      result.drift = topDrift(scene, centres);
      result.overlap = largestOverlap(scene, centres);
      world.free();
    }
  const median = (values) => [...values].sort((a, b) => a - b)[values.length >> 1];
  const jostleMs = median(results.get("jostle")?.times ?? [NaN]);
  for (const engine of engines) {
    const result = results.get(engine.name), ms = median(result.times);
    rows.push({scene: name, bodies: scene.bodies.length, engine: engine.name, ms, ratio: ms / jostleMs,
               drift: result.drift, overlap: result.overlap});
    if (!options.markdown)
      console.log(`${name.padEnd(17)} ${engine.name.padEnd(12)} ${ms.toFixed(2).padStart(9)} ms/step ` +
                  `${(ms / jostleMs).toFixed(2).padStart(7)}x jostle  drift ${result.drift === null ? "-" : result.drift.toFixed(4)}` +
                  `  overlap ${result.overlap.toFixed(4)}`);
  }
}
if (options.markdown) {
  console.log("| scene | bodies | engine | ms/step | its time / jostle's | top drift | largest overlap |");
  console.log("|---|---:|---|---:|---:|---:|---:|");
  for (const r of rows)
    console.log(`| ${r.scene} | ${r.bodies} | ${r.engine} | ${r.ms.toFixed(2)} | ${r.ratio.toFixed(2)} | ` +
                `${r.drift === null ? "" : r.drift.toFixed(4)} | ${r.overlap.toFixed(4)} |`);
}
console.log("\nSettings: " + engines.map((e) => `${e.name}: ${e.settings}`).join("; "));
