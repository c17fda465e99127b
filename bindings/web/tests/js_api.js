// The JavaScript API (page/jostle.js, docs/web.md) in Node, over the module the page
// loads: every argument of every jostle.World method, and of the module-level functions,
// is refused when it is the wrong kind, with a message that names the function and the
// argument, before it can reach the module as some other value (a body number of
// undefined or NaN read as body 0, 1.9 as body 1); the module's own errors name the
// function and what the caller passed, not the scene the module wrapped it in, in
// JavaScript's notation and counting; body numbers are given again after destroy, so that
// a million bodies made and destroyed leave boxes() listing the two live ones, the body
// numbers small and the module's heap as it was; and every row of every table of settings
// (src/body_properties.hpp, src/world_options.hpp, as jostle-test-rows lists them) reaches
// the world from a definition.
// jostle.version is the version of include/jostle/version.h, which CMake passes.
//   node js_api.js <page dir> <version> <jostle-test-rows>
"use strict";

const {execFileSync} = require("node:child_process");
const fs = require("node:fs");
const path = require("node:path");

let failures = 0;
function check(ok, what) {
  console.log(`${ok ? "ok  " : "FAIL"} ${what}`);
  if (!ok) failures++;
}

/// The page's two scripts, jostle-web.js (the module's loader, built for the web) and
/// jostle.js, run one after the other as a page runs them (in one function's scope here,
/// not a vm context: a value passed between two contexts costs ten times as much, and
/// the churn below makes a million bodies). Returns their Jostle class.
function loadPageScripts(pageDir) {
  const read = (file) => fs.readFileSync(path.join(pageDir, file), "utf8");
  return new Function(`${read("jostle-web.js")}\n${read("jostle.js")}\nreturn Jostle;`)();
}

/// Runs `call`, which must throw an error of the class named `type` whose message is
/// exactly `message`.
function refuses(what, call, type, message) {
  let error = null;
  try {
    call();
  } catch (e) {
    error = e;
  }
  if (error === null) return check(false, `${what} is refused (it returned)`);
  const ok = error.constructor.name === type && error.message === message;
  check(ok, `${what}: ${error.constructor.name}: ${error.message}` +
            (ok ? "" : `\n       expected ${type}: ${message}`));
}

/// Every argument, wrong, for every method: the message names the function and the
/// argument; nothing reached the module (the world is as it was).
function argumentChecks(jostle) {
  const world = jostle.createWorld({gravity: [0, 800]});
  const floor = world.createBody({type: "static", x: 0, y: 300, hw: 400, hh: 10});
  const crate = world.createBody({x: 0, y: 0, hw: 10, hh: 10, character: true});
  check(floor === 0 && crate === 1, `the first bodies are 0 and 1 (${floor}, ${crate})`);
  const before = JSON.stringify(world.boxes());

  const bodyNumber = (fn, got) =>
    ["TypeError", `${fn}: body must be a body number (an integer >= 0), got ${got}`];
  const number = (fn, name, got) => ["TypeError", `${fn}: ${name} must be a finite number, got ${got}`];
  // Not a body number: these were body 0 (undefined, NaN, null), body 1 (1.9, "1").
  for (const [value, shown] of [[undefined, "undefined"], [NaN, "NaN"], [null, "null"], [1.9, "1.9"],
                                ["1", '"1"'], [-1, "-1"], [Infinity, "Infinity"], [{}, "an object"]]) {
    refuses(`body(${shown})`, () => world.body(value), ...bodyNumber("body", shown));
    refuses(`destroyBody(${shown})`, () => world.destroyBody(value), ...bodyNumber("destroyBody", shown));
    refuses(`setVelocity(${shown}, 5, 5)`, () => world.setVelocity(value, 5, 5),
            ...bodyNumber("setVelocity", shown));
  }
  // An integer past the module's int32 was body 1 (2^32 + 1 wrapped round).
  refuses("body(2 ** 32 + 1)", () => world.body(2 ** 32 + 1), "Error", "body: no such body: 4294967297");
  refuses("setPosition(2 ** 31, 0, 0)", () => world.setPosition(2 ** 31, 0, 0), "Error",
          "setPosition: no such body: 2147483648");
  refuses("body(7), a body never made", () => world.body(7), "Error", "body: no such body: 7");
  refuses("setPosition(undefined, 0, 0)", () => world.setPosition(undefined, 0, 0),
          ...bodyNumber("setPosition", "undefined"));
  refuses("applyImpulse(NaN, 0, 0)", () => world.applyImpulse(NaN, 0, 0), ...bodyNumber("applyImpulse", "NaN"));
  refuses("setWalkSpeed(0.5, 1)", () => world.setWalkSpeed(0.5, 1), ...bodyNumber("setWalkSpeed", "0.5"));
  refuses("dropThrough(undefined, 1)", () => world.dropThrough(undefined, 1),
          ...bodyNumber("dropThrough", "undefined"));

  // Numbers: finite numbers, not strings, not NaN; within a float, which the module takes.
  refuses("setVelocity(crate, '5', 5)", () => world.setVelocity(crate, "5", 5), ...number("setVelocity", "vx", '"5"'));
  refuses("setVelocity(crate, 5, NaN)", () => world.setVelocity(crate, 5, NaN), ...number("setVelocity", "vy", "NaN"));
  refuses("setVelocity(crate, 5)", () => world.setVelocity(crate, 5), ...number("setVelocity", "vy", "undefined"));
  refuses("setVelocity(crate, 1e300, 0)", () => world.setVelocity(crate, 1e300, 0), "TypeError",
          "setVelocity: vx must be a finite number, got 1e+300, past a 32-bit float (±3.4e38)");
  refuses("setPosition(crate, Infinity, 0)", () => world.setPosition(crate, Infinity, 0),
          ...number("setPosition", "x", "Infinity"));
  refuses("setPosition(crate, 0, null)", () => world.setPosition(crate, 0, null), ...number("setPosition", "y", "null"));
  refuses("applyImpulse(crate, [1], 0)", () => world.applyImpulse(crate, [1], 0), ...number("applyImpulse", "ix", "an array"));
  refuses("applyImpulse(crate, 0, -Infinity)", () => world.applyImpulse(crate, 0, -Infinity),
          ...number("applyImpulse", "iy", "-Infinity"));
  refuses("setWalkSpeed(crate, NaN)", () => world.setWalkSpeed(crate, NaN), ...number("setWalkSpeed", "speed", "NaN"));
  refuses("dropThrough(crate, '1')", () => world.dropThrough(crate, "1"), ...number("dropThrough", "seconds", '"1"'));
  refuses("step()", () => world.step(), ...number("step", "dt", "undefined"));
  refuses("step(NaN)", () => world.step(NaN), ...number("step", "dt", "NaN"));
  refuses("step('1/60')", () => world.step("1/60"), ...number("step", "dt", '"1/60"'));

  // Definitions: objects, every value of them checked and named by its place.
  const box = {x: 0, y: 0, hw: 1, hh: 1};
  for (const [value, shown] of [[undefined, "undefined"], [null, "null"], [[], "an array"], ['{"x": 0}', '"{\\"x\\": 0}"'],
                                [5, "5"]])
    refuses(`createBody(${shown})`, () => world.createBody(value), "TypeError",
            `createBody: def must be an object, got ${shown}`);
  refuses("createBody({radius: NaN, ...})", () => world.createBody({...box, radius: NaN}), "TypeError",
          "createBody: radius: expected a finite number, got NaN");
  refuses("createBody({x: Infinity, ...})", () => world.createBody({...box, x: Infinity}), "TypeError",
          "createBody: x: expected a finite number, got Infinity");
  refuses("createBody({oneWay: [0, -Infinity], ...})", () => world.createBody({...box, oneWay: [0, -Infinity]}),
          "TypeError", "createBody: oneWay[1]: expected a finite number, got -Infinity");
  refuses("createBody({bounce: undefined, ...})", () => world.createBody({...box, bounce: undefined}), "TypeError",
          "createBody: bounce: expected a value, got undefined (leave a field out for its default)");
  refuses("createBody({hw: () => 1, ...})", () => world.createBody({...box, hw: () => 1}), "TypeError",
          "createBody: hw: expected a number, string, boolean, array or object, got a function");
  refuses("createBody({hw: 1n, ...})", () => world.createBody({...box, hw: 1n}), "TypeError",
          "createBody: hw: expected a number, string, boolean, array or object, got 1n");
  const cyclic = {...box};
  cyclic.self = cyclic;
  refuses("createBody of an object that contains itself", () => world.createBody(cyclic), "TypeError",
          "createBody: self: contains itself");

  // The module's errors: named by the function and the caller's own field, not by the
  // scene createBody is read as ("bodies[0].hw"), and said once ("step: step: ...").
  refuses("createBody({hw: -1, ...})", () => world.createBody({...box, hw: -1}), "Error", "createBody: hw: must be > 0");
  refuses("createBody({radius: -1, ...})", () => world.createBody({...box, radius: -1}), "Error",
          "createBody: radius: must be >= 0");
  refuses("createBody({foo: 1, ...})", () => world.createBody({...box, foo: 1}), "Error", 'createBody: unknown field "foo"');
  refuses("createBody({x: 0})", () => world.createBody({x: 0, y: 0, hw: 1}), "Error", 'createBody: missing field "hh"');
  refuses("createBody({type: 'x', ...})", () => world.createBody({...box, type: "x"}), "Error",
          'createBody: type: expected one of "static", "kinematic", "dynamic"');
  refuses("createBody({bounce: null, ...})", () => world.createBody({...box, bounce: null}), "Error",
          "createBody: bounce: expected a number, got null");
  refuses("step(-1)", () => world.step(-1), "Error", "step: dt must be a finite number > 0");
  refuses("setVelocity(floor, 5, 5)", () => world.setVelocity(floor, 5, 5), "Error",
          "setVelocity: a static body cannot move (make it kinematic)");
  refuses("dropThrough(crate, -1)", () => world.dropThrough(crate, -1), "Error",
          "dropThrough: seconds must be a finite number >= 0");
  refuses("setPosition(crate, 1e10, 0)", () => world.setPosition(crate, 1e10, 0), "Error",
          "setPosition: centre must be of magnitude <= 1e9");
  const classic = jostle.createWorld({solver: "classic"});
  refuses("createBody({radius: 0.5}) in the classic model", () => classic.createBody({...box, radius: 0.5}), "Error",
          'createBody: radius: the classic model has sharp boxes only (solver "classic")');
  classic.destroy();

  check(JSON.stringify(world.boxes()) === before, "nothing refused reached the world: its bodies are as they were");

  // Module-level functions.
  for (const [value, shown] of [[5, "5"], [null, "null"], [[], "an array"]])
    refuses(`createWorld(${shown})`, () => jostle.createWorld(value), "TypeError",
            `createWorld: scene must be an object or a scene file's text, got ${shown}`);
  refuses("createWorld({gravity: [0, NaN]})", () => jostle.createWorld({gravity: [0, NaN]}), "TypeError",
          "createWorld: gravity[1]: expected a finite number, got NaN");
  refuses("createWorld with a body of hw NaN", () => jostle.createWorld({bodies: [box, {...box, hw: NaN}]}),
          "TypeError", "createWorld: bodies[1].hw: expected a finite number, got NaN");
  refuses("createWorld with a body of hw 0", () => jostle.createWorld({bodies: [box, {...box, hw: 0}]}), "Error",
          "createWorld: bodies[1].hw: must be > 0");

  // A destroyed world refuses every call, whatever world has its number now.
  world.destroy();
  const other = jostle.createWorld({bodies: [box]});
  refuses("step after destroy()", () => world.step(1 / 60), "Error", "step: the world was destroyed");
  refuses("body(0) after destroy()", () => world.body(0), "Error", "body: the world was destroyed");
  refuses("createBody after destroy()", () => world.createBody(box), "Error", "createBody: the world was destroyed");
  refuses("destroy() twice", () => world.destroy(), "Error", "destroy: the world was destroyed");
  check(other.boxes().length === 1, "the world made after it is untouched");
  other.destroy();
}

/// One rule, in JavaScript's words (docs/reliability.md, "Misuse of the APIs"): an unknown
/// field names the known one it was probably meant to be; vectors are arrays, [0, -1];
/// rows count from 0 and are named by their place in the call's argument; a definition's
/// field is written as the object passed would hold it ("character: true").
function messages(jostle) {
  const world = jostle.createWorld({gravity: [0, 800]});
  const box = {x: 0, y: 0, hw: 1, hh: 1};
  const crate = world.createBody(box);
  refuses("createBody({snapdown: 4, ...})", () => world.createBody({...box, snapdown: 4}), "Error",
          'createBody: unknown field "snapdown" (did you mean "snapDown"?)');
  refuses("createBody({foo: 4, ...})", () => world.createBody({...box, foo: 4}), "Error",
          'createBody: unknown field "foo"');
  refuses("createWorld({gravty: [0, 1]})", () => jostle.createWorld({gravty: [0, 1]}), "Error",
          'createWorld: unknown field "gravty" (did you mean "gravity"?)');
  refuses("createWorld({tilemap: {tiles: 16, ...}})",
          () => jostle.createWorld({tilemap: {tiles: 16, rows: ["#"]}}), "Error",
          'createWorld: tilemap: unknown field "tiles" (did you mean "tile"?)');
  refuses("createBody({oneWay: [1, 1], ...})", () => world.createBody({...box, oneWay: [1, 1]}), "Error",
          "createBody: oneWay: must be [0, 0] or one of [1, 0], [-1, 0], [0, 1], [0, -1]");
  refuses("createWorld with a ragged tile map",
          () => jostle.createWorld({tilemap: {tile: 16, rows: ["#..#", "###"]}}), "Error",
          "createWorld: tilemap.rows[1]: has 3 columns, rows[0] has 4");
  refuses("createWorld with a tile that is no tile's",
          () => jostle.createWorld({tilemaps: [{tile: 16, rows: ["#"]}, {tile: 16, rows: ["#{"]}]}), "Error",
          "createWorld: tilemaps[1].rows[0][1]: expected '#', '.' or a ramp, got '{'");
  refuses("setWalkSpeed(crate, 50), not a character", () => world.setWalkSpeed(crate, 50), "Error",
          "setWalkSpeed: the body is not a character (a dynamic body with character: true)");
  check(world.boxes().length === 1, "nothing refused reached the world");
  world.destroy();
}

/// A destroyed body's number is refused until it is given again; createBody gives the
/// smallest number no live body has; boxes() lists the live bodies in creation order.
function numbersAfterDestroy(jostle) {
  const world = jostle.createWorld({bodies: [0, 1, 2, 3].map((i) => ({x: 10 * i, y: 0, hw: 1, hh: 1}))});
  world.destroyBody(2);
  refuses("body(2) once destroyed", () => world.body(2), "Error", "body: no such body: 2");
  refuses("destroyBody(2) twice", () => world.destroyBody(2), "Error", "destroyBody: no such body: 2");
  world.destroyBody(0);
  const a = world.createBody({x: 100, y: 0, hw: 1, hh: 1});
  const b = world.createBody({x: 200, y: 0, hw: 1, hh: 1});
  const c = world.createBody({x: 300, y: 0, hw: 1, hh: 1});
  check(a === 0 && b === 2 && c === 4, `the smallest free numbers are given again: ${a}, ${b}, ${c} (0, 2, 4)`);
  check(world.body(0).x === 100, "number 0 names the new body now");
  const listed = world.boxes().map((box) => `${box.body}@${box.x}`).join(" ");
  check(listed === "1@10 3@30 0@100 2@200 4@300", `boxes() lists the live bodies in creation order: ${listed}`);
  world.destroy();
}

/// A million bodies made and destroyed beside two that stay: boxes() lists the two, the
/// numbers stay small, and the module's heap is what it was after the first thousand.
function churn(jostle) {
  const m = jostle.module;
  const world = jostle.createWorld({gravity: [0, 800]});
  world.createBody({type: "static", x: 0, y: 300, hw: 400, hh: 10});
  world.createBody({x: 0, y: 280, hw: 10, hh: 10});
  const cycle = () => {
    const body = world.createBody({x: 50, y: 0, hw: 1, hh: 1});
    world.destroyBody(body);
    return body;
  };
  for (let i = 0; i < 1000; i++) cycle();
  world.boxes();
  const heapCounter = typeof m._jostle_web_heap_in_use === "function";
  const inUse = () => (heapCounter ? m._jostle_web_heap_in_use() : NaN);
  const memoryBefore = m.HEAP8.length;
  const inUseBefore = inUse();

  const kCycles = 1000000;
  let largest = 0;
  const start = Date.now();
  for (let i = 0; i < kCycles; i++) largest = Math.max(largest, cycle());
  const seconds = (Date.now() - start) / 1000;

  const boxes = world.boxes();
  check(boxes.length === 2 && boxes[0].body === 0 && boxes[1].body === 1 && boxes[0].y === 300,
        `after ${kCycles} bodies made and destroyed (${seconds.toFixed(1)} s), boxes() lists the two live ones: ` +
        JSON.stringify(boxes.map((box) => box.body)));
  check(boxes.every((box) => Number.isInteger(box.body)), "boxes() gives body numbers as integers");
  // Numbers are given again, so they never pass the most bodies alive at once (3 here):
  // they stay far from 2^24, where a float would round them, and within the int32 that
  // boxes() reads them as.
  check(largest === 2, `every body made in the churn had number 2 (the largest given: ${largest})`);
  // The heap: two bodies live before and after, so what the module holds must be what it
  // held. Anything kept per body made, even one byte, would add 1,000,000 bytes; the
  // bound, 64 KiB, is far below that and far above an allocator's slack. The memory
  // itself grows by at least a fifth at a time (emscripten's growth step), so it must not
  // have grown at all.
  check(heapCounter, "the module reports its heap in use (jostle_web_heap_in_use)");
  const grown = inUse() - inUseBefore;
  check(grown < 65536, `the heap in use grew by ${grown} bytes (< 65536; ${inUseBefore} bytes in use before)`);
  check(m.HEAP8.length === memoryBefore,
        `the module's memory stayed ${(memoryBefore / 2 ** 20).toFixed(1)} MiB (now ${(m.HEAP8.length / 2 ** 20).toFixed(1)} MiB)`);
  world.destroy();
}

/// A conveyor made from JavaScript (issue 29): a static belt whose surface moves at -90
/// carries a character standing on it at -90 after a few steps, as in C++.
function conveyor(jostle) {
  const world = jostle.createWorld({gravity: [0, 800]});
  world.createBody({type: "static", x: 0, y: 300, hw: 400, hh: 10, surfaceVelocity: [-90, 0]});
  const hero = world.createBody({x: 0, y: 282, hw: 6, hh: 8, character: true});
  for (let i = 0; i < 20; i++) world.step(1 / 60);
  const {vx} = world.body(hero);
  check(Math.abs(vx + 90) < 1e-3, `a character on a belt moves with its surface: vx ${vx}`);
  world.destroy();
}

/// Every row of every table of settings, from a definition: JavaScript's definitions are
/// scene files' (jostle.js writes them as JSON for the module's scene loader), so a row a
/// file holds is taken, and a value of the wrong type for it is refused by its name: the
/// loader reads it. A body's rows are given back by bodyDef as they were given (as floats
/// keep them), and what it gives makes the same body. A row no file holds (a pointer, the
/// task system's workers) is refused as an unknown field.
function everyRow(jostle, rows) {
  const refusal = (call) => {
    try {
      call();
    } catch (e) {
      return e.message;
    }
    return "";
  };
  const seen = new Set();
  const givenBack = new Set();
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
        const read = bodies.bodyDef(body);
        check(JSON.stringify(read[row.name]) === JSON.stringify(asKept(value)),
              `${what}: bodyDef gives back ${JSON.stringify(read[row.name])} (${JSON.stringify(value)})`);
        givenBack.add(row.name);
        const again = bodies.createBody(read); // what it gives, createBody takes
        check(JSON.stringify(bodies.bodyDef(again)) === JSON.stringify(read), `${what}: bodyDef makes the same body`);
      };
      place = row.name;
      fn = "createBody";
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
        `every body row a file holds is given back by bodyDef: ${[...givenBack].join(", ")}`);
  for (const table of ["world", "tasks", "classic", "physical", "body", "tileMap"])
    check(seen.has(table), `jostle-test-rows lists the rows of ${table}`);
}

/// Snapshots: a rolled-back world steps on as it did the first time (the same state hash,
/// the same boxes), keeps the body numbers of its snapshot, and refuses what is not one.
function snapshots(jostle) {
  const world = jostle.createWorld({gravity: [0, 600]});
  world.createBody({type: "static", x: 0, y: 10, hw: 200, hh: 10});
  for (let i = 0; i < 6; i++) world.createBody({x: i * 11 - 30, y: -10 - 12 * i, hw: 5, hh: 5, bounce: 0.4});
  for (let i = 0; i < 20; i++) world.step(1 / 60);
  const saved = world.snapshot();
  check(saved instanceof Uint8Array && String.fromCharCode(...saved.subarray(0, 8)) === "JSTLSNAP",
        "snapshot() is a Uint8Array of a snapshot's bytes");
  const hash = world.stateHash();
  check(/^[0-9a-f]{16}$/.test(hash), `stateHash() is 16 hexadecimal digits: ${hash}`);
  world.destroyBody(3);
  const extra = world.createBody({x: 100, y: -40, hw: 3, hh: 3});
  for (let i = 0; i < 60; i++) world.step(1 / 60);
  const later = JSON.stringify(world.boxes()), laterHash = world.stateHash();

  world.restore(saved);
  check(world.stateHash() === hash, "restored: the snapshot's state hash");
  check(world.boxes().length === 7 && world.boxes().some((b) => b.body === 3),
        "body 3, destroyed since, is back under its number");
  world.destroyBody(3);
  check(world.createBody({x: 100, y: -40, hw: 3, hh: 3}) === extra, "the same calls give the same numbers");
  for (let i = 0; i < 60; i++) world.step(1 / 60);
  check(JSON.stringify(world.boxes()) === later && world.stateHash() === laterHash,
        "rolled back and stepped again: the same boxes and state, bit for bit");

  // Another world, from the bytes alone: numbered in creation order.
  const other = jostle.createWorld({});
  other.restore(saved);
  check(other.stateHash() === hash && other.boxes().map((b) => b.body).join() === "0,1,2,3,4,5,6",
        "restored in another world: the same state, bodies numbered in creation order");
  refuses("restore('text')", () => world.restore("text"), "TypeError",
          'restore: snapshot must be a Uint8Array (from snapshot()), got "text"');
  refuses("restore(a cut snapshot)", () => world.restore(saved.subarray(0, 40)), "Error",
          `restore: truncated snapshot: 40 bytes, its header says ${saved.length}`);
  check(world.stateHash() === laterHash, "refused, the world is as it was");
  world.destroy();
  other.destroy();
}

async function main() {
  const [pageDir, version, rowsProgram] = process.argv.slice(2);
  const Jostle = loadPageScripts(path.resolve(pageDir));
  const wasmBinary = fs.readFileSync(path.join(pageDir, "jostle-web.wasm"));
  const jostle = await Jostle.load({wasmBinary});
  check(jostle.version === version, `jostle.version is ${jostle.version}, version.h says ${version}`);
  let loadError = "";
  try {
    // (Were it not refused it would load without the bytes, and might never settle.)
    await Promise.race([Jostle.load(null), new Promise((resolve) => setTimeout(resolve, 5000))]);
  } catch (e) {
    loadError = `${e.constructor.name}: ${e.message}`;
  }
  check(loadError === "TypeError: Jostle.load: options must be an object, got null",
        `Jostle.load(null) is refused: ${loadError}`);
  const rows = execFileSync(rowsProgram, {encoding: "utf8"}).trim().split("\n").map((line) => JSON.parse(line));
  const everyRowOf = (j) => everyRow(j, rows);
  Object.defineProperty(everyRowOf, "name", {value: "everyRow"});
  for (const part of [argumentChecks, messages, numbersAfterDestroy, churn, conveyor, snapshots, everyRowOf]) {
    try {
      part(jostle);
    } catch (error) {
      check(false, `${part.name} threw: ${error.stack}`);
    }
  }
  console.log(failures === 0 ? "all passed" : `${failures} failed`);
  process.exit(failures === 0 ? 0 : 1);
}

main().catch((error) => {
  console.log(`FAILED: ${error.stack}`);
  process.exit(1);
});
