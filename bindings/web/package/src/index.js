// jostle for JavaScript and TypeScript (docs/javascript.md): 2D collision detection and
// response for games, over jostle's C API built to WebAssembly.
//
//     import {load} from "jostle";
//     const jostle = await load();
//     const world = jostle.createWorld({gravity: [0, 800]});
//     world.createBody({type: "static", x: 0, y: 300, hw: 400, hh: 10});
//     const crate = world.createBody({x: 0, y: 0, hw: 10, hh: 10, bounce: 0.3});
//     world.step(1 / 60);
//     console.log(crate.position);
import * as args from "./args.js";
import {Runtime} from "./runtime.js";
import {World} from "./world.js";
import {FixedStep} from "./fixed_step.js";
import {compile} from "./wasm.js";
import {instantiate} from "./module.js";
export {World} from "./world.js";
export {Body} from "./body.js";
export {TileMap} from "./tile_map.js";
export {FixedStep} from "./fixed_step.js";

/// A debug-draw colour (0xRRGGBBAA) as CSS writes it, "#rrggbbaa": for a canvas's
/// fillStyle and strokeStyle.
export function cssColour(colour) {
  return `#${(args.bits("cssColour", "colour", colour) >>> 0).toString(16).padStart(8, "0")}`;
}

/// Loads the module. `options.wasm`: jostle.wasm's bytes (an ArrayBuffer or a typed
/// array), a compiled WebAssembly.Module, its URL (a URL or a string) or a Response (or a
/// promise of one); by default the jostle.wasm beside this file, found through
/// import.meta.url (read from disk in Node, fetched in a page or a worker).
export async function load(options = {}) {
  args.object("load", "options", options);
  for (const key of Object.keys(options))
    if (key !== "wasm") throw new TypeError(`load: no option "${key}" (wasm)`);
  let wasm;
  try {
    wasm = await compile(options.wasm ?? new URL("./jostle.wasm", import.meta.url));
  } catch (error) {
    throw new Error(`load: jostle.wasm could not be loaded: ${error.message ?? error}`);
  }
  const jostle = new Jostle();
  jostle.start(await instantiate(wasm));
  return jostle;
}

/// The loaded module: makes worlds and fixed steps.
export class Jostle {
  start(module) {
    this.rt = new Runtime(module);
    /// The library's version, "major.minor.patch".
    this.version = this.rt.text(module._jostle_version());
    this.worlds = new Map(); // jostle_world* → World, for the callbacks
    this.moveFilter = null; // the filter of the move under way
    this.thrown = null; // what a callback threw, rethrown when the C call returns
    module.jostlePreSolve = (collision, world) => this.preSolve(collision, world);
    module.jostleMoveFilter = (other, world) => this.filterMove(other, world);
  }

  /// A world from a scene: an object or a scene file's text (docs/scene-format.md), its
  /// tile maps and bodies made too (world.bodies() lists them in the file's order).
  createWorld(scene = {}) {
    const fn = "createWorld";
    if (typeof scene !== "string")
      if (typeof scene !== "object" || scene === null || Array.isArray(scene))
        throw new TypeError(`${fn}: scene must be an object or a scene file's text, got ${args.describe(scene)}`);
    const text = typeof scene === "string" ? scene : args.json(fn, {bodies: [], ...scene});
    // The scene loader reads the text into jostle.h's definitions (web_c_api.cpp), which
    // jostle.h's functions then create, as a C program would.
    return this.make(fn, () => this.rt.withText(text, (p) => this.rt.m._jostle_web_read_scene(p))).world;
  }

  /// A level drawn in Tiled (docs/levels.md), from its JSON text (.tmj): {world, objects}.
  /// `options.name` names it in errors ("level.tmj"); `options.files` holds the texts of
  /// the files it names (external tilesets, .tsj) by their paths. Each object is {name,
  /// type, layer, id, x, y, hw, hh, properties, body, bodies}: body the Body made from it
  /// or null, bodies every one (a polygon makes one a side).
  loadTiled(text, options = {}) {
    const fn = "loadTiled";
    const {name, files} = this.levelOptions(fn, text, options, ["name", "files"]);
    return this.make(fn, () => this.withTexts([text, name, files], ([t, n, f]) => this.rt.m._jostle_web_read_tiled(t, n, f)));
  }

  /// A level of an LDtk project, by its identifier, from the project's text: {world,
  /// objects}, as loadTiled. `options.kinds` says what IntGrid values are ({4: "none"});
  /// `options.files` holds the texts of levels saved apart (.ldtkl) by their paths.
  loadLdtk(text, level, options = {}) {
    const fn = "loadLdtk";
    if (typeof level !== "string") throw new TypeError(`${fn}: level must be a level's identifier, got ${args.describe(level)}`);
    const {name, files, kinds} = this.levelOptions(fn, text, options, ["name", "files", "kinds"]);
    return this.make(fn, () => this.withTexts([text, name, level, files, kinds],
                                              (p) => this.rt.m._jostle_web_read_ldtk(...p)));
  }

  /// The options of loadTiled and loadLdtk, checked, the files and kinds as JSON.
  levelOptions(fn, text, options, known) {
    if (typeof text !== "string") throw new TypeError(`${fn}: text must be the file's text, got ${args.describe(text)}`);
    args.object(fn, "options", options);
    for (const key of Object.keys(options))
      if (!known.includes(key)) throw new TypeError(`${fn}: no option "${key}" (${known.join(", ")})`);
    const name = options.name ?? (fn === "loadTiled" ? "level.tmj" : "level.ldtk");
    if (typeof name !== "string") throw new TypeError(`${fn}: options.name must be a string, got ${args.describe(name)}`);
    const files = args.object(fn, "options.files", options.files ?? {});
    for (const [path, content] of Object.entries(files))
      if (typeof content !== "string") throw new TypeError(`${fn}: options.files[${JSON.stringify(path)}] must be the file's text`);
    const kinds = args.object(fn, "options.kinds", options.kinds ?? {});
    for (const [value, kind] of Object.entries(kinds))
      if (!/^-?\d+$/.test(value) || typeof kind !== "string")
        throw new TypeError(`${fn}: options.kinds must map IntGrid values to kinds ("solid", "oneWay", "none", a ramp's character), got ${value}: ${args.describe(kind)}`);
    return {name, files: JSON.stringify(files), kinds: JSON.stringify(kinds)};
  }

  /// Calls `call` with pointers to `texts` in the module's memory, as UTF-8; frees them after.
  withTexts(texts, call, pointers = []) {
    if (pointers.length === texts.length) return call(pointers);
    return this.rt.withText(texts[pointers.length], (p) => this.withTexts(texts, call, [...pointers, p]));
  }

  /// A world made from what `read` kept (a scene, a level) in the module: {world,
  /// objects}, the objects a level's, each with its bodies.
  make(fn, read) {
    const rt = this.rt, m = rt.m;
    const def = read();
    rt.check(fn, def !== 0);
    try {
      const pointer = m._jostle_world_create(def);
      rt.check(fn, pointer !== 0);
      const world = new World(this, pointer), bodies = [];
      try {
        for (let i = 0, map; (map = m._jostle_web_scene_tile_map(i)) !== 0; i++) {
          m._jostle_tile_map_create(rt.out, pointer, map);
          rt.check(fn, m.HEAPU32[(rt.out >> 2) + 1] !== 0);
        }
        for (let i = 0, body; (body = m._jostle_web_scene_body(i)) !== 0; i++) {
          m._jostle_body_create(rt.out, pointer, body);
          rt.check(fn, m.HEAPU32[(rt.out >> 2) + 1] !== 0);
          bodies.push(world.bodyAt(rt.out));
        }
      } catch (error) {
        world.destroy();
        throw error;
      }
      const objects = typeof m._jostle_web_level_objects === "function"
        ? JSON.parse(rt.text(m._jostle_web_level_objects())) : [];
      for (const object of objects) {
        object.bodies = bodies.slice(Math.max(object.body, 0), Math.max(object.body, 0) + object.bodyCount);
        object.body = object.body >= 0 ? bodies[object.body] : null;
        delete object.bodyCount;
      }
      return {world, objects};
    } finally {
      m._jostle_web_forget_scene();
    }
  }

  /// A clock of steps of `dt` seconds, at most `maxStepsPerFrame` a frame (default 8).
  createFixedStep(dt, maxStepsPerFrame = 8) {
    return new FixedStep(this, dt, maxStepsPerFrame);
  }

  // --- Callbacks from the module -------------------------------------------------------------

  /// What a callback threw is kept and thrown when the C call returns (a callback must
  /// return normally to C): a move whose filter threw moves nothing; a step whose
  /// pre-solve threw is finished as if the callback had said true from then on.
  rethrow() {
    const thrown = this.thrown;
    if (thrown !== null) {
      this.thrown = null;
      this.rt.m._jostle_clear_error(); // the C call's own error, if the callback caused one
      throw thrown;
    }
  }

  preSolve(at, pointer) {
    const world = this.worlds.get(pointer);
    if (this.thrown !== null || world === undefined || world.preSolve === null) return true;
    const rt = this.rt, L = rt.layout.collision;
    const collision = {a: world.bodyAt(at + L.a), b: world.bodyAt(at + L.b), normal: rt.vec(at + L.normal),
                       depth: rt.float(at + L.depth), bounce: rt.float(at + L.bounce),
                       friction: rt.float(at + L.friction)};
    try {
      const respond = world.preSolve(collision) !== false;
      checkCollision(collision);
      const floats = rt.m.HEAPF32;
      floats[(at + L.bounce) >> 2] = collision.bounce;
      floats[(at + L.friction) >> 2] = collision.friction;
      return respond;
    } catch (error) {
      this.thrown = error;
      return true;
    }
  }

  filterMove(at, pointer) {
    const world = this.worlds.get(pointer);
    if (this.thrown !== null || world === undefined || this.moveFilter === null) return 0;
    try {
      const answer = this.moveFilter(world.bodyAt(at));
      const response = ["slide", "touch", "cross", "bounce", "ignore"].indexOf(answer);
      if (response < 0)
        throw new TypeError(`move: filter must return "slide", "touch", "cross", "bounce" or "ignore", got ${args.describe(answer)}`);
      return response;
    } catch (error) {
      this.thrown = error;
      return -1; // not a response: the C API refuses the move, and nothing moves
    }
  }
}

const kCollisionFields = ["a", "b", "normal", "depth", "bounce", "friction"];

/// What the pre-solve callback left in its collision, checked as Lua checks it: no field
/// but its own (a typo must not pass silently), bounce and friction numbers in [0, 1].
function checkCollision(collision) {
  for (const key in collision)
    if (!kCollisionFields.includes(key))
      throw new TypeError(`step: the pre-solve callback's collision has no field "${key}" (${kCollisionFields.join(", ")})`);
  for (const key of ["bounce", "friction"]) {
    const value = collision[key];
    if (typeof value !== "number" || !(value >= 0 && value <= 1))
      throw new TypeError(`step: the pre-solve callback's collision.${key} must be a number in [0, 1], got ${args.describe(value)}`);
  }
}
