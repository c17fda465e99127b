// The npm package's API in Node, method by method, over the package directory the build
// fills: each answer is one a reader can work out from the scene (a box dropped 280 units
// meets the floor at about sqrt(2 g h), a ray from above meets a box's top face...), each
// refusal names the method and the argument, and reading every body's position makes no
// garbage.
// Every row of every table of settings (src/body_properties.hpp, src/world_options.hpp, as
// jostle-test-rows lists them) reaches a world from a definition; bodies made and destroyed
// by the hundred thousand leave the module's heap as it was.
//   node --expose-gc api.mjs <package dir> <version> <jostle-test-rows>
import path from "node:path";
import {existsSync} from "node:fs";
import {readFile} from "node:fs/promises";
import {pathToFileURL} from "node:url";
import {execFileSync} from "node:child_process";

const [packageDir, version, rowsProgram] = process.argv.slice(2);
if (!existsSync(path.join(packageDir, "jostle.mjs"))) {
  console.log(`SKIPPED: no package in ${packageDir} (the web build makes it where esbuild is installed)`);
  process.exit(77);
}
const {load, cssColour, Body, World, TileMap} = await import(pathToFileURL(path.join(packageDir, "jostle.mjs")).href);

let failures = 0;
function check(ok, what) {
  console.log(`${ok ? "ok  " : "FAIL"} ${what}`);
  if (!ok) failures++;
}
const near = (a, b, tolerance = 1e-4) => Math.abs(a - b) <= tolerance;

/// `call` must throw a `type` whose message is exactly `message`.
function refuses(what, call, type, message) {
  try {
    call();
  } catch (error) {
    const ok = error.constructor.name === type && error.message === message;
    return check(ok, `${what}: ${error.constructor.name}: ${error.message}` + (ok ? "" : `\n       expected ${type}: ${message}`));
  }
  check(false, `${what} is refused (it returned)`);
}

async function rejects(what, promise, message) {
  try {
    await promise;
    check(false, `${what} is refused (it resolved)`);
  } catch (error) {
    check(error.message.startsWith(message), `${what}: ${error.message}`);
  }
}

// --- Loading ------------------------------------------------------------------------------
const jostle = await load();
check(jostle.version === version, `load() finds jostle.wasm beside the file: version ${jostle.version}`);
const bytes = await readFile(path.join(packageDir, "jostle.wasm"));
check((await load({wasm: bytes})).version === version, "load({wasm: bytes})");
check((await load({wasm: await WebAssembly.compile(bytes)})).version === version, "load({wasm: a WebAssembly.Module})");
check((await load({wasm: new Response(bytes)})).version === version, "load({wasm: a Response})");
await rejects("a wasm that is not there", load({wasm: pathToFileURL("/nonexistent/jostle.wasm")}),
              "load: jostle.wasm could not be loaded: ENOENT");
await rejects("bytes that are not wasm", load({wasm: new Uint8Array([1, 2, 3])}), "load: jostle.wasm could not be loaded");
await rejects("an unknown option", load({wasmBinary: bytes}), "load: no option \"wasmBinary\" (wasm)");

// --- Worlds ---------------------------------------------------------------------------------
{
  const world = jostle.createWorld({gravity: [0, 800], bodies: [{type: "static", x: 0, y: 300, hw: 400, hh: 10},
                                                               {x: 0, y: 0, hw: 10, hh: 10}]});
  check(world instanceof World && world.bodyCount === 2, "a scene's bodies are made with its world");
  const [floor, box] = world.bodies();
  check(floor instanceof Body && floor.type === "static" && box.type === "dynamic", "bodies() in the file's order");
  check(world.bodies()[1] === box, "a body is one object wherever it is met");
  check(near(world.gravity.y, 800) && world.solver === "physical" && world.sleeping && world.workers === 1,
        "the world's settings read back");
  world.gravity = [0, 400];
  check(world.gravity.y === 400, "gravity set from [x, y]");
  world.gravity = {x: 1, y: 2};
  check(world.gravity.x === 1 && world.gravity.y === 2, "gravity set from {x, y}");
  refuses("a gravity without y", () => { world.gravity = {x: 1}; }, "TypeError",
          "gravity: gravity.y must be a finite number, got undefined");
  check(world.maxVelocity === Infinity, "no velocity clamp by default");
  world.maxVelocity = 100;
  check(world.maxVelocity === 100, "maxVelocity set");
  refuses("a maxVelocity of 0", () => { world.maxVelocity = 0; }, "Error",
          "maxVelocity: maxVelocity must be > 0 (infinity for no clamp)");
  world.physicalOptions = {velocityIterations: 8, frictionMix: "geometricMean"};
  const physical = world.physicalOptions;
  check(physical.velocityIterations === 8 && physical.frictionMix === "geometricMean" && physical.positionIterations === 3,
        "physicalOptions: the fields given change, the others stay");
  refuses("a frictionMix that is not one", () => { world.physicalOptions = {frictionMix: "max"}; }, "TypeError",
          "physicalOptions: physicalOptions.frictionMix must be \"min\" or \"geometricMean\", got \"max\"");
  world.solver = "classic";
  world.classicOptions = {mass: true};
  check(world.solver === "classic" && world.classicOptions.mass && !world.classicOptions.ccd, "the classic model and its switches");
  refuses("an unknown solver", () => { world.solver = "verlet"; }, "TypeError",
          "solver: must be \"classic\" or \"physical\", got \"verlet\"");
  world.destroy();
  refuses("a destroyed world", () => world.step(1 / 60), "Error", "step: the world was destroyed");
  refuses("a body of a destroyed world", () => box.position, "Error", "position: the world was destroyed");
  check(!box.valid, "a body of a destroyed world is not valid");
  refuses("a scene with a bad body", () => jostle.createWorld({bodies: [{hw: 1, hh: 1}, {hw: 0, hh: 1}]}), "Error",
          "createWorld: bodies[1].hw: must be > 0");
  refuses("a scene file's text with a mistake", () => jostle.createWorld('{"gravity": [0, 800], "bodeis": []}'), "Error",
          "createWorld: unknown field \"bodeis\" (did you mean \"bodies\"?)");
  refuses("a scene that is a number", () => jostle.createWorld(3), "TypeError",
          "createWorld: scene must be an object or a scene file's text, got 3");
}

// --- Bodies ---------------------------------------------------------------------------------
{
  const world = jostle.createWorld({gravity: [0, 800]});
  const body = world.createBody({x: 1, y: 2, hw: 3, hh: 4, userData: {name: "crate"}});
  check(body.userData.name === "crate" && body.def().userData.name === "crate", "userData is any value, kept");
  // Values a float holds exactly, so that each reads back as set.
  const settings = {bounce: 0.25, friction: 0.75, mass: 2.5, gravityScale: -1, damping: 0.5, bullet: true,
                    category: 0x80000000, mask: 6, character: true, wallFriction: 0.125, floorAngle: 45,
                    cornerCorrection: 2, stepUp: 3, snapDown: 4, walkSpeed: 150};
  for (const [name, value] of Object.entries(settings)) {
    body[name] = value;
    check(body[name] === value, `body.${name} = ${value} reads back`);
  }
  for (const [name, value] of [["position", {x: 5, y: 6}], ["velocity", {x: 7, y: 8}], ["halfExtents", {x: 2, y: 1}],
                               ]) {
    body[name] = [value.x, value.y];
    check(body[name].x === value.x && body[name].y === value.y, `body.${name} = [${value.x}, ${value.y}] reads back`);
  }
  refuses("a conveyor that is dynamic", () => { body.surfaceVelocity = [9, 0]; }, "Error",
          "surfaceVelocity: a conveyor must be static or kinematic");
  body.oneWay = [0, -1];
  check(body.oneWay.y === -1, "body.oneWay reads back");
  body.setDensity(2);
  check(body.mass === 2 * 4 * 2 * 1, "setDensity: mass = density * 4 hw hh");
  body.sensor = true;
  check(body.sensor, "body.sensor reads back");
  body.type = "kinematic";
  check(body.type === "kinematic", "body.type reads back");
  body.surfaceVelocity = {x: 9, y: 0};
  check(body.surfaceVelocity.x === 9, "body.surfaceVelocity reads back");
  const def = body.def();
  check(def.type === "kinematic" && def.x === 5 && def.hw === 2 && def.bounce === 0.25, "def() is a scene file's body");
  refuses("friction NaN", () => { body.friction = NaN; }, "TypeError", "friction: friction must be a finite number, got NaN");
  refuses("friction past [0, 1]", () => { body.friction = 2; }, "Error", "friction: friction must be in [0, 1]");
  refuses("a mask past 32 bits", () => { body.mask = 2 ** 32; }, "TypeError",
          "mask: mask must be 32 bits: an integer in [0, 4294967295], or a bitwise result, got 4294967296");
  // JavaScript's bitwise operators give signed numbers: ~4 is -5, the bits 0xFFFFFFFB.
  body.mask = ~4;
  check(body.mask === 0xFFFFFFFB, `a mask from ~4 reads back unsigned (${body.mask})`);
  check(world.createBody({hw: 1, hh: 1, mask: ~2, category: 1 << 31}).mask === 0xFFFFFFFD,
        "a definition's bit fields from bitwise operators");
  refuses("a body type that is not one", () => { body.type = "ghost"; }, "TypeError",
          "type: must be \"static\", \"kinematic\" or \"dynamic\", got \"ghost\"");
  {
    const given = jostle.createWorld({gravity: {x: 0, y: 500}});
    const ledge = given.createBody({type: "static", hw: 4, hh: 1, oneWay: {x: 0, y: -1}});
    check(given.gravity.y === 500 && ledge.oneWay.y === -1 && ledge.oneWay.x === 0,
          "a definition's vectors may be {x, y}, as jostle gives them, as well as [x, y]");
    refuses("a vector of neither kind", () => given.createBody({hw: 1, hh: 1, surfaceVelocity: "east"}), "Error",
            "createBody: surfaceVelocity: expected an array of 2 numbers, got string");
    given.destroy();
  }
  refuses("a definition's mistake", () => world.createBody({hw: 1, hh: 1, bounce: 3}), "Error",
          "createBody: bounce: must be in [0, 1]");
  refuses("an unknown field", () => world.createBody({hw: 1, hh: 1, bouncy: 1}), "Error",
          "createBody: unknown field \"bouncy\" (did you mean \"bounce\"?)");
  refuses("undefined in a definition", () => world.createBody({hw: 1, hh: undefined}), "TypeError",
          "createBody: hh: expected a value, got undefined (leave a field out for its default)");
  refuses("a method's argument named as the method names it", () => body.setVelocity(NaN, 0), "TypeError",
          "setVelocity: vx must be a finite number, got NaN");
  body.destroy();
  check(!body.valid, "a destroyed body is not valid");
  refuses("a body destroyed twice", () => body.destroy(), "Error",
          "destroy: stale BodyId (the body was destroyed)");
  refuses("a stale body", () => body.position, "Error", "position: stale BodyId (the body was destroyed)");
  refuses("a stale body's setter", () => { body.friction = 0.5; }, "Error", "friction: stale BodyId (the body was destroyed)");
  refuses("a stale body's tile map", () => body.tileMap, "Error", "tileMap: stale BodyId (the body was destroyed)");
  const other = jostle.createWorld().createBody({hw: 1, hh: 1});
  refuses("a body of another world", () => world.createBody({hw: 1, hh: 1}).isTouching(other), "TypeError",
          "isTouching: other must be a Body of this world, got an object");
  world.destroy();
}

// --- Events, characters ---------------------------------------------------------------------
{
  const world = jostle.createWorld({gravity: [0, 800]});
  const floor = world.createBody({type: "static", x: 0, y: 300, hw: 400, hh: 10});
  const box = world.createBody({x: 0, y: 0, hw: 10, hh: 10});
  const coin = world.createBody({type: "static", x: 0, y: 150, hw: 5, hh: 5, sensor: true});
  let begin = null, sensorBegin = null, sensorEnd = null;
  for (let i = 0; i < 120; i++) {
    world.step(1 / 60);
    begin ??= world.contactBegins()[0] ?? null;
    sensorBegin ??= world.sensorBegins()[0] ?? null;
    sensorEnd ??= world.sensorEnds()[0] ?? null;
  }
  check(sensorBegin?.sensor === coin && sensorBegin?.visitor === box, "the falling box enters the coin's sensor");
  check(sensorEnd?.sensor === coin && sensorEnd?.visitor === box, "and leaves it");
  check(begin?.a === floor && begin?.b === box, "a contact begins between the floor (made first) and the box");
  check(begin.normal.x === 0 && begin.normal.y === 1, "its normal points from the box towards the floor");
  // 280 units of fall: sqrt(2 * 800 * 280) = 669, within a step's gain (800 / 60) of it.
  check(Math.abs(begin.approachSpeed - Math.sqrt(2 * 800 * 280)) < 800 / 60, `it meets at about sqrt(2 g h) (${begin.approachSpeed})`);
  check(near(begin.point.y, 290, 0.5), `where they touch: the floor's top, y = 290 (${begin.point.y})`);
  check(box.touching.floor && !box.touching.ceiling, "the box touches a floor");
  check(box.isTouching(floor), "isTouching");
  const contacts = box.contacts();
  // The box's mass is its area, 400: the floor holds it with m g dt = 400 * 800 / 60 a step.
  check(contacts.length === 1 && contacts[0].other === floor && near(contacts[0].impulse, 400 * 800 / 60, 0.5),
        `contacts(): the floor, an impulse of m g dt = 5333 a step (${contacts[0]?.impulse})`);
  box.destroy();
  world.step(1 / 60);
  const end = world.contactEnds();
  check(end.length === 1 && end[0].a === floor && end[0].b === box && !end[0].b.valid, "a destroyed body's contact ends");

  const hero = world.createBody({x: 100, y: 280, hw: 6, hh: 10, character: true});
  world.step(1 / 60);
  check(hero.ground?.body === floor && hero.ground.normal.y === -1, "a character's ground is the floor");
  hero.walkSpeed = 120;
  world.step(1 / 60);
  check(hero.velocity.x === 120, "it walks at the speed set (120)");
  hero.setVelocity(120, -300);
  world.step(1 / 60);
  check(hero.ground === null, "in the air it has no ground");

  // A kinematic lid coming down on a crate on the floor crushes it.
  const crate = world.createBody({x: -100, y: 280, hw: 10, hh: 10});
  const lid = world.createBody({type: "kinematic", x: -100, y: 250, hw: 30, hh: 10, vy: 60});
  let crush = null;
  for (let i = 0; i < 60 && crush === null; i++) {
    world.step(1 / 60);
    crush = world.crushBegins()[0] ?? null;
  }
  check(crush?.body === crate && crush?.by === lid && crush?.against === floor, "a crush: the crate, by the lid, against the floor");
  check(world.profile().step > 0 && "solve" in world.profile(), "profile() has every stage");
  world.destroy();
}

// --- Queries --------------------------------------------------------------------------------
{
  const world = jostle.createWorld();
  const floor = world.createBody({type: "static", x: 0, y: 100, hw: 100, hh: 10});
  const box = world.createBody({type: "static", x: 0, y: 0, hw: 10, hh: 10});
  const sensor = world.createBody({type: "static", x: 50, y: 0, hw: 5, hh: 5, sensor: true});
  check(world.queryPoint([0, 95])[0] === floor, "queryPoint");
  check(world.queryPoint([50, 0]).length === 0 && world.queryPoint([50, 0], {includeSensors: true})[0] === sensor,
        "sensors only when asked");
  check(world.queryBox([0, 50], [20, 45]).length === 2, "queryBox: the box and the floor");
  check(world.queryRect([-5, -5], [5, 5])[0] === box, "queryRect");
  const hit = world.rayCast([0, -100], [0, 200]);
  check(hit?.body === box && hit.point.y === -10 && hit.normal.y === -1 && near(hit.fraction, 90 / 300),
        "rayCast meets the box's top face at y = -10, 90 / 300 of the way");
  check(world.rayCast([0, -100], [0, 200], {ignore: box}).body === floor, "rayCast ignoring the box meets the floor");
  check(world.rayCastAll([0, -100], [0, 200]).map((h) => h.body).join() === [box, floor].join() &&
        world.rayCastAll([0, -100], [0, 200])[1].body === floor, "rayCastAll: nearest first");
  const cast = world.boxCast([30, 0], [5, 5], [0, 200]);
  check(cast?.body === floor && cast.centre.y === 85, "boxCast stops a box of half 5 on the floor's top (y = 85)");
  const circle = world.circleCast([30, 0], 5, [0, 200]);
  check(circle?.body === floor && near(circle.centre.y, 85), "circleCast likewise");
  check(world.roundedBoxCast([30, 0], [5, 5], 2, [0, 200])?.body === floor, "roundedBoxCast");
  const slid = world.moveAndSlide([30, 80], [5, 5], [20, 20]);
  check(slid.centre.x === 50 && slid.centre.y === 85 && slid.hits[0].body === floor,
        "moveAndSlide into the floor slides along it: (50, 85)");
  refuses("a filter with an unknown field", () => world.queryPoint([0, 0], {layers: 1}), "TypeError",
          "queryPoint: filter has no field \"layers\" (mask, category, includeSensors, ignore)");
  check(world.rayCast([30, 0], [30, 200], {ignore: undefined, mask: ~0})?.body === floor,
        "a filter's field undefined is its default, and a mask may be a bitwise result");
  refuses("a filter's mask of no 32 bits", () => world.queryPoint([0, 0], {mask: 1.5}), "TypeError",
          "queryPoint: filter.mask must be 32 bits: an integer in [0, 4294967295], or a bitwise result, got 1.5");

  const mover = world.createBody({type: "kinematic", x: -50, y: 0, hw: 5, hh: 5});
  let moved = mover.move(100, 0);
  check(moved.x === -15 && moved.collisions[0].other === box && moved.collisions[0].response === "slide",
        "move stops at the box's side (x = -15)");
  moved = mover.move(100, 0, () => "cross");
  check(moved.x === 85 && moved.collisions[0].response === "cross", "a filter that crosses goes through");
  refuses("a filter's error", () => mover.move(-100, 0, () => { throw new Error("boom"); }), "Error", "boom");
  check(mover.position.x === 85, "a move whose filter threw moves nothing");
  refuses("a filter's wrong answer", () => mover.move(-100, 0, () => "stick"), "TypeError",
          "move: filter must return \"slide\", \"touch\", \"cross\", \"bounce\" or \"ignore\", got \"stick\"");
  world.destroy();
}

// --- Tile maps ------------------------------------------------------------------------------
{
  const world = jostle.createWorld();
  const map = world.createTileMap({x: 0, y: 0, tile: 16, rows: ["#..#", "####"]});
  check(map instanceof TileMap && map.columns === 4 && map.rows === 2, "a tile map of 4 x 2");
  check(map.bodies().length === 3 && map.bodies()[0].tileMap === map, "merged runs: two tiles and a row, three bodies");
  check(map.tileOf(1, 0) === "." && map.isSolid(0, 0) && map.tileOf(9, 9) === ".", "tileOf and isSolid");
  const tile = map.tileAt([20, 20]);
  check(tile.column === 1 && tile.row === 1 && map.tileAt([-1, 0]) === null, "tileAt");
  map.setTile(1, 0, "#");
  map.setTile(2, 0, "#");
  check(map.bodies().length === 1, "filling the gap makes the map one solid block: one body");
  refuses("a tile that is not one", () => map.setTile(0, 0, "x"), "Error",
          "setTile: expected '#', '.' or a ramp, got 'x'");
  refuses("a map with a bad row", () => world.createTileMap({tile: 16, rows: ["#", "##"]}), "Error",
          "createTileMap: rows[1]: has 2 columns, rows[0] has 1");
  const labelled = world.createTileMap({x: 100, tile: 16, rows: ["#"], userData: "spikes"});
  check(labelled.userData === "spikes" && labelled.bodies()[0].tileMap.userData === "spikes",
        "a tile map's userData, kept on it, reached from its bodies");
  labelled.destroy();
  map.destroy();
  check(!map.valid && world.bodyCount === 0, "a destroyed map takes its bodies");
  world.destroy();
}

// --- The fixed step, pre-solve, snapshots -------------------------------------------------------
{
  const world = jostle.createWorld();
  const runner = world.createBody({x: 0, y: 0, hw: 1, hh: 1, vx: 60});
  const clock = jostle.createFixedStep(1 / 60);
  check(clock.dt === Math.fround(1 / 60) && clock.maxStepsPerFrame === 8, "a clock of 1/60 s, 8 steps a frame at most");
  const steps = clock.update(world, 0.04);
  // 0.04 s is 2 steps of 1/60 and 0.4 of a third.
  check(steps === 2 && near(clock.alpha, 0.4, 1e-3), `0.04 s: 2 steps and alpha 0.4 (${steps}, ${clock.alpha})`);
  check(near(clock.drawPosition(runner).x, 1 + 0.4, 1e-3), `drawn between x = 1 and 2 by alpha (${clock.drawPosition(runner).x})`);
  refuses("a clock's bad dt, in the method's words", () => jostle.createFixedStep(0), "Error",
          "createFixedStep: dt must be a number of seconds from 1e-6 to 3600");
  refuses("a negative frame, in the method's words", () => clock.advance(-1), "Error",
          "advance: frameSeconds must be a finite number >= 0");
  const drawn = new Float32Array(2);
  check(clock.readDrawPositions(world, drawn) === 1 && near(drawn[0], 1.4, 1e-3), "readDrawPositions");
  clock.destroy();
  // Each step's events through afterStep: boxes landing in the first, third and sixth of a
  // frame's eight steps (fallen g dt² n(n + 1) / 2 after n steps: gaps of 0.1, 1 and 4.5).
  const landings = (eachStep) => {
    const w = jostle.createWorld({gravity: [0, 1000]});
    w.createBody({type: "static", y: 10, hw: 100, hh: 10});
    for (const gap of [0.1, 1, 4.5]) w.createBody({x: 10 * gap, y: -1 - gap, hw: 1, hh: 1});
    const c = jostle.createFixedStep(1 / 60, 8);
    let begins = 0;
    if (eachStep) check(c.update(w, 8 / 60, () => { begins += w.contactBegins().length; }) === 8, "eight steps");
    else {
      c.update(w, 8 / 60);
      begins = w.contactBegins().length;
    }
    c.destroy();
    w.destroy();
    return begins;
  };
  check(landings(true) === 3, "update's afterStep sees every step's events");
  check(landings(false) < 3, "read after the frame, the last step's alone");
  // Reset forgets where bodies were: a restored world is drawn where it is.
  {
    const w = jostle.createWorld({gravity: [0, 0]});
    const box = w.createBody({hw: 1, hh: 1, vx: 4});
    const start = w.snapshot(), c = jostle.createFixedStep(0.25);
    c.update(w, 0.25);
    c.update(w, 0.375); // from 1 to 2, alpha 0.5
    w.restore(start);
    check(near(c.drawPosition(box).x, 0.5, 1e-6), "between 1 (before the step) and 0");
    c.reset();
    check(c.drawPosition(box).x === 0, "drawn where it is after reset()");
    c.advance(0.25);
    c.rememberPositions(w);
    w.step(0.25);
    c.advance(0.125);
    check(near(c.drawPosition(box).x, 0.5, 1e-6), "stepped by hand: between 0 and 1 by alpha 0.5");
    refuses("an afterStep that is not a function", () => c.update(w, 1, 5), "TypeError",
            "update: afterStep must be a function, got 5");
    c.destroy();
    w.destroy();
  }
  world.destroy();
}
{
  const world = jostle.createWorld({gravity: [0, 800]});
  world.createBody({type: "static", x: 0, y: 100, hw: 100, hh: 10});
  const ghost = world.createBody({x: -50, y: 0, hw: 5, hh: 5});
  const ball = world.createBody({x: 50, y: 0, hw: 5, hh: 5});
  world.setPreSolve((c) => {
    if (c.b === ghost) return false;
    c.bounce = 1;
    return true;
  });
  let highest = Infinity;
  for (let i = 0; i < 60; i++) {
    world.step(1 / 60);
    if (i > 30) highest = Math.min(highest, ball.position.y);
  }
  check(ghost.position.y > 110, `a pair the callback refuses passes through: the ghost fell through (${ghost.position.y})`);
  check(highest < 40, `a bounce set to 1 sends the ball back up (to y = ${highest.toFixed(1)})`);
  world.setPreSolve((c) => { c.frcition = 0; });
  refuses("a field the collision does not have", () => { for (let i = 0; i < 120; i++) world.step(1 / 60); }, "TypeError",
          "step: the pre-solve callback's collision has no field \"frcition\" (a, b, normal, depth, bounce, friction)");
  world.setPreSolve((c) => { c.friction = "high"; });
  refuses("a friction that is no number", () => { for (let i = 0; i < 120; i++) world.step(1 / 60); }, "TypeError",
          "step: the pre-solve callback's collision.friction must be a number in [0, 1], got \"high\"");
  world.setPreSolve(() => { throw new Error("callback failed"); });
  refuses("a pre-solve's error", () => { for (let i = 0; i < 120; i++) world.step(1 / 60); }, "Error", "callback failed");
  world.setPreSolve(null);
  world.step(1 / 60);

  const saved = world.snapshot(), hash = world.stateHash();
  check(world.snapshotSize() === saved.length, "snapshotSize() is the length of a snapshot");
  const room = new Uint8Array(saved.length + 7), kept = world.snapshot(room);
  check(kept.buffer === room.buffer && kept.length === saved.length && kept.every((b, i) => b === saved[i]),
        "snapshot(into) writes the same bytes into the front of `into`");
  const short = new Uint8Array(saved.length - 1), grown = world.snapshot(short);
  check(grown.buffer !== short.buffer && grown.length === saved.length,
        "snapshot(into) with `into` too short gives a new array");
  refuses("snapshot into what is not a Uint8Array", () => world.snapshot([]), "TypeError",
          "snapshot: into must be a Uint8Array, got an array");
  const later = world.createBody({x: 0, y: -50, hw: 1, hh: 1});
  ghost.destroy();
  world.step(1 / 60);
  world.restore(saved);
  check(world.stateHash() === hash && /^[0-9a-f]{16}$/.test(hash), "restore gives the snapshot's state hash back");
  check(ghost.valid && !later.valid, "a body destroyed since is back under its handle; one made since is stale");
  refuses("a snapshot that is not one", () => world.restore(new Uint8Array(10)), "Error",
          "restore: not a jostle snapshot");
  check(world.stateHash() === hash, "a refused restore leaves the world as it was");

  // Restored into another world, the bodies are adopted by their slot and generation.
  {
    const other = jostle.createWorld();
    other.restore(saved);
    const adopted = other.adopt(ball);
    check(adopted !== null && adopted.world === other && adopted.position.x === ball.position.x &&
          adopted.position.y === ball.position.y, "adopt: the other world's body of the same slot");
    check(other.adopt(later) === null, "adopt: none for a body the snapshot does not hold");
    refuses("adopting what is no handle", () => other.adopt(5), "TypeError",
            "adopt: other must be a Body or a TileMap, got 5");
    other.destroy();
  }
  // A body made after a restore under the handle of one made after the snapshot is the same
  // object (rollback makes the same handles again), with its own def's userData.
  const bullet = world.createBody({x: 0, y: -80, hw: 1, hh: 1, userData: {kind: "bullet"}});
  world.restore(saved);
  const rocket = world.createBody({x: 50, y: 10, hw: 3, hh: 3});
  check(rocket === bullet && rocket.userData === undefined,
        `a body made again under a handle has its own def's userData (${JSON.stringify(rocket.userData)})`);
  // A slot reused after the snapshot, then restored: the body back in it is one object
  // again, with no userData (docs/snapshots.md: its slot did not hold it last).
  ball.userData = "ball";
  const before = world.snapshot();
  ball.destroy();
  const reuser = world.createBody({x: 0, y: -60, hw: 1, hh: 1});
  check(reuser.index === ball.index, "the slot of a destroyed body is reused");
  world.restore(before);
  const inSlot = () => world.bodies().find((b) => b.index === ball.index);
  const again = inSlot();
  check(again === inSlot() && again.generation === ball.generation && again.userData === undefined,
        "restored, a body whose slot was reused since is one object, without userData");
  world.destroy();
}

// --- Every body's shape, for drawing ------------------------------------------------------
{
  const world = jostle.createWorld();
  world.createBody({type: "static", x: 0, y: 0, hw: 4, hh: 2});
  world.createBody({x: 0, y: -10, hw: 3, hh: 3, radius: 3, sensor: true});
  world.createBody({type: "static", x: 10, y: 0, hw: 5, hh: 5, slope: [-1, -1], segment: true});
  const shapes = new Float32Array(18);
  check(world.readShapes(shapes) === 3, "readShapes: three bodies");
  check(shapes.slice(0, 6).join() === "4,2,0,0,0,16", "a static box, awake: 4, 2, no radius, no slope, flags 16");
  check(shapes.slice(6, 12).join() === "3,3,3,0,0,22", "a dynamic circle sensor, awake: radius 3, flags 2 + 4 + 16");
  check(shapes.slice(12, 18).join() === "5,5,0,-1,-1,24", "a segment: slope -1, -1, flags 8 + 16");
  world.destroy();
}

// --- Debug drawing (docs/debug-draw.md) ----------------------------------------------------
{
  const world = jostle.createWorld({gravity: [0, 10], sleeping: false});
  world.createBody({type: "static", x: 0, y: 1, hw: 10, hh: 1});
  world.createBody({x: 0, y: -0.5, hw: 0.5, hh: 0.5, radius: 0.5});
  world.createBody({type: "static", x: 10, y: 20, hw: 2, hh: 1, slope: [1, -1]});
  for (let i = 0; i < 60; i++) world.step(1 / 60);
  const calls = [];
  const recorder = {
    line: (...a) => calls.push(["line", ...a]),
    box: (...a) => calls.push(["box", ...a]),
    roundedBox: (...a) => calls.push(["roundedBox", ...a]),
    triangle: (...a) => calls.push(["triangle", ...a]),
    point: (...a) => calls.push(["point", ...a]),
  };
  world.debugDraw(recorder);
  check(calls.length === 3, "debugDraw: a call a body");
  // Static grey 150 150 150 opaque, outlined at 60 %: 90 90 90.
  check(calls[0].join() === ["box", 0, 1, 10, 1, 0x969696ff, 0x5a5a5aff].join(), "the floor: its box and colours");
  check(calls[1][0] === "roundedBox" && calls[1][5] === 0.5, "the ball: a rounded box of radius 0.5");
  // The slope names the corner (+x, -y): the face runs (12, 21) to (8, 19), the right angle at (8, 21).
  check(calls[2].slice(0, 7).join() === "triangle,12,21,8,19,8,21", "the ramp: the triangle its slope leaves");
  calls.length = 0;
  world.debugDraw(recorder, {shapes: false, contacts: true, markLength: 0.25});
  const point = calls.find((c) => c[0] === "point"), normal = calls.find((c) => c[0] === "line");
  check(calls.length === 2 && near(point[2], 0, 1e-2) && near(normal[4] - normal[2], -0.25, 1e-6),
        "a contact: its point on the floor and its normal up into the ball, markLength long");
  let lines = 0;
  world.debugDraw({line: () => lines++}, null);
  check(lines === 4 + 3 + 4 * 6, "a renderer of lines alone gets every shape in lines: the box's 4, the ramp's 3, the ball's 4 arcs of 6");
  calls.length = 0;
  world.debugDraw(recorder, {viewMin: [-1, -1], viewMax: {x: 1, y: 1}, palette: {staticBody: 0x102030ff, outlinePercent: 50}});
  check(calls.length === 2 && calls[0][5] === 0x102030ff && calls[0][6] === 0x081018ff,
        "the view leaves the ramp out; the palette's colour and percentage");
  calls.length = 0;
  world.debugDraw(recorder, {contacts: undefined, markLength: undefined, palette: {staticBody: undefined}});
  check(calls.length === 3 && calls[0][5] === 0x969696ff, "options left undefined are their defaults");
  check(cssColour(0xff8000ff) === "#ff8000ff" && cssColour(0x10) === "#00000010", "cssColour: #rrggbbaa");
  refuses("no line", () => world.debugDraw({}), "TypeError", "debugDraw: draw.line must be a function, got undefined");
  refuses("a box that is not a function", () => world.debugDraw({line() {}, box: 3}), "TypeError",
          "debugDraw: draw.box must be a function, got 3");
  refuses("a negative mark", () => world.debugDraw({line() {}}, {markLength: -1}), "Error",
          "debugDraw: options.markLength must be a finite number >= 0");
  refuses("a percentage past 100", () => world.debugDraw({line() {}}, {palette: {sleepingPercent: 101}}), "Error",
          "debugDraw: options.palette.sleepingPercent must be in [0, 100]");
  refuses("an unknown option", () => world.debugDraw({line() {}}, {grd: true}), "TypeError",
          "debugDraw: options has no field \"grd\" (shapes, contacts, velocities, touching, grid, markLength, viewMin, viewMax, palette)");
  refuses("an unknown colour", () => world.debugDraw({line() {}}, {palette: {floor: 1}}), "TypeError",
          "debugDraw: options.palette has no field \"floor\"");
  refuses("a palette name in C's spelling", () => world.debugDraw({line() {}}, {palette: {static_body: 1}}), "TypeError",
          "debugDraw: options.palette has no field \"static_body\"");
  refuses("drawing again from a function of debugDraw", () => world.debugDraw({line() { world.debugDraw({line() {}}); }}),
          "Error", "debugDraw: called from a function of debugDraw");
  let thrown = null;
  try {
    world.debugDraw({line() {}, box() { throw new Error("from the renderer"); }});
  } catch (error) {
    thrown = error;
  }
  check(thrown?.message === "from the renderer", "the renderer's own error comes out of debugDraw");
  world.destroy();
}

// --- Reading every body makes no garbage -------------------------------------------------------
{
  const world = jostle.createWorld({gravity: [0, 800]});
  for (let i = 0; i < 1000; i++) world.createBody({x: (i % 40) * 3, y: -(i / 40 | 0) * 3, hw: 1, hh: 1});
  const positions = new Float32Array(2 * world.bodyCount);
  // Warmed up first: V8 compiles a hot function, which allocates on the heap once. V8 may
  // still be optimising during a window (on a busy machine, once, three windows in a row
  // grew 24 bytes a read: code not yet optimised); garbage made by each read shows in every
  // window, so the least of up to ten windows is the reads' own. Each window's growth is
  // in the message.
  for (let i = 0; i < 20000; i++) world.readPositions(positions);
  const windows = [];
  while (windows.length < 10 && !(Math.min(...windows) < 10000)) {
    globalThis.gc();
    const before = process.memoryUsage().heapUsed;
    for (let i = 0; i < 10000; i++) world.readPositions(positions);
    windows.push(process.memoryUsage().heapUsed - before);
  }
  const grown = Math.min(...windows);
  // A single object a call would be 10,000 objects, hundreds of KB.
  check(grown < 10000, `10,000 reads of 1,000 positions make no garbage (the heap grew ${grown} bytes; windows: ${windows.join(", ")})`);
  check(positions[0] === 0 && positions[2] === 3, "and read them");
  world.destroy();
}

// --- Every row of every table of settings, from a definition ------------------------------
// Definitions are scene files' (the package writes them as JSON for the module's scene
// loader), so a row a file holds is taken, and a value of the wrong type for it is refused
// by its name. A body's rows are given back by def() as they were given (as floats keep
// them), and what it gives makes the same body. A row no file holds (the task system's
// workers) is refused as an unknown field; userData is any JavaScript value.
{
  const rows = execFileSync(rowsProgram, {encoding: "utf8"}).trim().split("\n").map((line) => JSON.parse(line));
  const refusal = (call) => {
    try {
      call();
    } catch (e) {
      return e.message;
    }
    return "";
  };
  const seen = new Set(), givenBack = new Set();
  const bodies = jostle.createWorld();
  for (const row of rows) {
    seen.add(row.table);
    const what = `${row.table}.${row.name}`;
    const wrong = typeof row.sample === "string" ? 1 : "x";
    const def = (value) => ({...row.needs, [row.name]: value});
    // How a value of the row reaches a world, and the place its messages name.
    let make, place, fn = "createWorld";
    if (row.table === "world" || row.table === "tasks") {
      make = (value) => jostle.createWorld(def(value)).destroy();
      place = row.name;
    } else if (row.table === "classic" || row.table === "physical") {
      make = (value) => jostle.createWorld({[row.table]: def(value)}).destroy();
      place = `${row.table}.${row.name}`;
    } else if (row.table === "tileMap") {
      make = (value) => jostle.createWorld({tilemap: def(value)}).destroy();
      place = `tilemap.${row.name}`;
    } else {
      make = (value) => {
        const body = bodies.createBody(def(value));
        if (value !== row.sample) return;
        // As the body keeps it: a fraction as a 32-bit float, a whole number (bits) whole.
        const asKept = (v) => typeof v === "number" && !Number.isInteger(v) ? Math.fround(v)
                            : Array.isArray(v) ? v.map(asKept) : v;
        const read = body.def();
        check(JSON.stringify(read[row.name]) === JSON.stringify(asKept(value)),
              `${what}: def() gives back ${JSON.stringify(read[row.name])} (${JSON.stringify(value)})`);
        givenBack.add(row.name);
        const again = bodies.createBody(read); // what it gives, createBody takes
        check(JSON.stringify(again.def()) === JSON.stringify(read), `${what}: def() makes the same body`);
      };
      place = row.name;
      fn = "createBody";
    }
    if (what === "body.userData") { // any JavaScript value, kept on the Body instead
      const value = {any: "value"};
      check(bodies.createBody({...row.needs, userData: value}).userData === value, `${what} is kept on the Body`);
      continue;
    }
    if (!row.file) {
      const message = refusal(() => make(row.pointer ? {} : row.sample));
      const where = place.includes(".") ? `${place.slice(0, place.lastIndexOf("."))}: ` : "";
      check(message.startsWith(`${fn}: ${where}unknown field "${row.name}"`),
            `${what}, which no file holds, is refused: ${message}`);
      continue;
    }
    const taken = refusal(() => make(row.sample));
    check(taken === "", `${what} = ${JSON.stringify(row.sample)} is taken${taken ? `: ${taken}` : ""}`);
    const message = refusal(() => make(wrong));
    check(message.startsWith(`${fn}: ${place}: expected`), `${what} of the wrong type is refused by its name: ${message}`);
  }
  bodies.destroy();
  const bodyRows = rows.filter((row) => row.table === "body" && row.file).map((row) => row.name);
  check(bodyRows.length > 20 && bodyRows.every((name) => givenBack.has(name)),
        `every body row a file holds is given back by def(): ${[...givenBack].join(", ")}`);
  for (const table of ["world", "tasks", "classic", "physical", "body", "tileMap"])
    check(seen.has(table), `jostle-test-rows lists the rows of ${table}`);
}

// --- A conveyor (issue 29): a character on a belt whose surface moves at -90 moves at -90 --
{
  const world = jostle.createWorld({gravity: [0, 800]});
  world.createBody({type: "static", x: 0, y: 300, hw: 400, hh: 10, surfaceVelocity: [-90, 0]});
  const hero = world.createBody({x: 0, y: 282, hw: 6, hh: 8, character: true});
  for (let i = 0; i < 20; i++) world.step(1 / 60);
  check(near(hero.velocity.x, -90, 1e-3), `a character on a belt moves with its surface: vx ${hero.velocity.x}`);
  world.destroy();
}

// --- Bodies made and destroyed by the hundred thousand beside two that stay ---------------
// The module's heap is what it was after the first thousand: anything kept per body made,
// even one byte, would add 200,000 bytes; the bound, 64 KiB, is far below that and far
// above an allocator's slack. The memory grows a fifth at a time, so it must not have.
{
  const m = jostle.rt.m;
  const world = jostle.createWorld({gravity: [0, 800]});
  const floor = world.createBody({type: "static", x: 0, y: 300, hw: 400, hh: 10});
  const crate = world.createBody({x: 0, y: 280, hw: 10, hh: 10});
  const cycle = () => world.createBody({x: 50, y: 0, hw: 1, hh: 1}).destroy();
  for (let i = 0; i < 1000; i++) cycle();
  const memoryBefore = m.HEAP8.length, inUseBefore = m._jostle_web_heap_in_use();
  const kCycles = 200000;
  for (let i = 0; i < kCycles; i++) cycle();
  const bodies = world.bodies();
  check(bodies.length === 2 && bodies[0] === floor && bodies[1] === crate,
        `after ${kCycles} bodies made and destroyed, bodies() lists the two live ones`);
  const grown = m._jostle_web_heap_in_use() - inUseBefore;
  check(grown < 65536, `the module's heap in use grew by ${grown} bytes (< 65536)`);
  check(m.HEAP8.length === memoryBefore, "the module's memory did not grow");
  check(world.bodyOfSlot.length <= 3, `the package keeps a Body for each slot, not each body made (${world.bodyOfSlot.length})`);
  world.destroy();
}

// --- Levels from Tiled and LDtk (docs/levels.md) -------------------------------------------
{
  const root = new URL("../../../../", import.meta.url);
  const read = (path) => readFile(new URL(path, root), "utf8");
  // The example level (examples/levels/level.tmj, its tileset embedded): two crates that
  // fall 40 units onto the floor (top at y 224) and rest at 216 and 200, stacked.
  const {world, objects} = jostle.loadTiled(await read("examples/levels/level.tmj"));
  const named = (name) => objects.filter((o) => o.name === name);
  check(named("spawn")[0]?.body === null && named("spawn")[0].x === 40 && named("spawn")[0].y === 200,
        "loadTiled: the spawn point is an object at (40, 200) with no body");
  check(named("lift")[0]?.body?.type === "kinematic" && named("lift")[0].properties.top === 104,
        "the lift is a kinematic body, its property top 104");
  check(named("coin").length === 3 && named("coin").every((coin) => coin.body.sensor), "three coins, each a sensor");
  for (let i = 0; i < 120; i++) world.step(1 / 60);
  const crates = named("crate").map((crate) => crate.body.position.y).sort((a, b) => b - a);
  check(near(crates[0], 216, 0.05) && near(crates[1], 200, 0.05), `the crates rest on the floor, stacked (${crates})`);
  world.destroy();
  refuses("a .tmx's text", () => jostle.loadTiled("<map/>", {name: "level.tmx"}), "Error",
          "loadTiled: level.tmx: XML maps (.tmx) are not read in this build: export the map as JSON (.tmj)");
  const await_text_of_external_map = await read("tests/level/maps/level_external.tmj");
  refuses("a map whose tileset is not given",
          () => jostle.loadTiled(await_text_of_external_map, {name: "level_external.tmj"}), "Error",
          "loadTiled: level_external.tmj: tileset \"tiles.tsj\": not given (pass its text in files)");
  const external = jostle.loadTiled(await_text_of_external_map,
                                    {name: "level_external.tmj", files: {"tiles.tsj": await read("tests/level/maps/tiles.tsj")}});
  check(external.objects.length === 6, "an external tileset given in files");
  external.world.destroy();

  const project = await read("tests/level/maps/level.ldtk");
  const ldtk = jostle.loadLdtk(project, "Level_0", {kinds: {4: "none"}});
  const crate = ldtk.objects.find((o) => o.name === "Crate");
  check(crate?.body?.type === "dynamic" && crate.body.friction === 0.25 && crate.x === 40 && crate.y === 8,
        "loadLdtk: the crate entity is a dynamic body at (40, 8) with its friction");
  ldtk.world.destroy();
  refuses("an IntGrid value with no kind", () => jostle.loadLdtk(project, "Level_0"), "Error",
          "loadLdtk: level.ldtk: level \"Level_0\": layer \"Collisions\": IntGrid value 4 (\"water\"): expected an " +
          "identifier \"solid\", \"oneWay\", \"none\", \"rampRight\", \"rampLeft\", \"ceilingRight\" or " +
          "\"ceilingLeft\", or the value in the kinds table");
  const apart = jostle.loadLdtk(project, "Level_1", {files: {"level_1.ldtkl": await read("tests/level/maps/level_1.ldtkl")}});
  check(apart.world.bodyCount === 1, "a level saved apart, given in files: its floor, one body");
  apart.world.destroy();
}

console.log(failures === 0 ? "all passed" : `${failures} failed`);
process.exitCode = failures === 0 ? 0 : 1;
