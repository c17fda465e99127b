// jostle.js: jostle in the browser, over the WebAssembly module jostle-web.js
// (bindings/web; docs/web.md). Load both scripts, then:
//
//     const jostle = await Jostle.load();
//     const world = jostle.createWorld({gravity: [0, 800]});
//     world.createBody({type: "static", x: 0, y: 300, hw: 400, hh: 10});
//     const crate = world.createBody({x: 0, y: 0, hw: 10, hh: 10, bounce: 0.3});
//     world.step(1 / 60);
//     const {x, y} = world.body(crate);
//
// It calls the C API (jostle.h, docs/c-api.md), which the module exports whole, as a C
// program would; web_c_api.cpp adds what C cannot say: a scene file's JSON read into
// jostle.h's definitions, and the last error in JavaScript's notation. Worlds and bodies
// are described as in scene files (docs/scene-format.md), and checked as they are: a
// mistake throws an Error naming the field. Every argument is checked before it reaches
// the module (JostleArgs): a wrong kind throws a TypeError naming the function and the
// argument. `jostle.page` drives the demo's samples, for the page itself (page.js).
"use strict";

/// The checks of the arguments a game passes, made before anything reaches the module:
/// each throws a TypeError that names the function, the argument and what it got. What
/// only the module knows (jostle's own rules: dt > 0, a static body does not move, a
/// definition's fields) it reports itself, in the C API's last error, which Jostle.check
/// throws as an Error that names the function too.
class JostleArgs {
  /// A body number: an integer >= 0. Returns it. (Whether a body has it is the world's
  /// to say: "no such body: 3", JostleWorld.handle.)
  static body(fn, value) {
    if (typeof value !== "number" || !Number.isInteger(value) || value < 0)
      throw new TypeError(`${fn}: body must be a body number (an integer >= 0), got ${JostleArgs.describe(value)}`);
    return value;
  }

  /// A finite number, which the module takes as a 32-bit float: a number past a float's
  /// range (±3.4e38) would reach it as an infinity, so it is refused here. Returns it.
  static number(fn, name, value) {
    if (typeof value !== "number" || !Number.isFinite(value))
      throw new TypeError(`${fn}: ${name} must be a finite number, got ${JostleArgs.describe(value)}`);
    if (!Number.isFinite(Math.fround(value)))
      throw new TypeError(`${fn}: ${name} must be a finite number, got ${value}, past a 32-bit float (±3.4e38)`);
    return value;
  }

  /// An object (not null, not an array). Returns it.
  static object(fn, name, value) {
    if (typeof value !== "object" || value === null || Array.isArray(value))
      throw new TypeError(`${fn}: ${name} must be an object, got ${JostleArgs.describe(value)}`);
    return value;
  }

  /// A definition (a scene, a body) as JSON for the module's scene loader. JSON.stringify
  /// would turn NaN and the infinities into null and leave out undefined, so that the
  /// loader would see a null or nothing where the game wrote a number; so every value is
  /// checked first, and a bad one is named by its place as the loader names places
  /// ("radius", "bodies[3].hw", "gravity[1]"): "createBody: radius: expected a finite
  /// number, got NaN". Leave a field out for its default: undefined is refused.
  static json(fn, value) {
    const problem = JostleArgs.jsonProblem(value, []);
    if (problem !== null) {
      let place = "";
      for (const key of problem.place.reverse())
        place += typeof key === "number" ? `[${key}]`
               : (place === "" ? "" : ".") + (/^[A-Za-z_][A-Za-z0-9_]*$/.test(key) ? key : JSON.stringify(key));
      throw new TypeError(`${fn}: ${place === "" ? "" : place + ": "}${problem.what}`);
    }
    return JSON.stringify(value);
  }

  /// What JSON.stringify would not write as it is, in `value`: {place: the keys and
  /// indices that lead to it, last first; what: the words of the error}, or null.
  /// (`within`: the objects around it, for a value that contains itself.)
  static jsonProblem(value, within) {
    switch (typeof value) {
      case "number":
        return Number.isFinite(value) ? null : {place: [], what: `expected a finite number, got ${value}`};
      case "string":
      case "boolean":
        return null;
      case "object": {
        if (value === null) return null;
        if (within.includes(value)) return {place: [], what: "contains itself"};
        if (typeof value.toJSON === "function")
          return {place: [], what: "expected a plain object or array, got an object with toJSON"};
        within.push(value);
        let problem = null;
        if (Array.isArray(value)) {
          for (let i = 0; i < value.length && problem === null; i++)
            if ((problem = JostleArgs.jsonProblem(value[i], within)) !== null) problem.place.push(i);
        } else {
          for (const key of Object.keys(value))
            if ((problem = JostleArgs.jsonProblem(value[key], within)) !== null) {
              problem.place.push(key);
              break;
            }
        }
        within.pop();
        return problem;
      }
      case "undefined":
        return {place: [], what: "expected a value, got undefined (leave a field out for its default)"};
      default:
        return {place: [], what: `expected a number, string, boolean, array or object, got ${JostleArgs.describe(value)}`};
    }
  }

  /// A value as an error message shows it: 3, NaN, undefined, null, "text", an array...
  static describe(value) {
    switch (typeof value) {
      case "string": return JSON.stringify(value.length > 40 ? value.slice(0, 40) + "..." : value);
      case "bigint": return `${value}n`;
      case "symbol": return "a symbol";
      case "function": return "a function";
      case "object": return value === null ? "null" : Array.isArray(value) ? "an array" : "an object";
      default: return String(value);
    }
  }
}

class Jostle {
  /// Loads the module; `options` go to emscripten's factory (locateFile, say).
  static async load(options = {}) {
    JostleArgs.object("Jostle.load", "options", options);
    return new Jostle(await createJostleModule(options));
  }

  constructor(module) {
    this.module = module;
    /// The library's version, "major.minor.patch" (jostle/version.h, jostle_version()).
    this.version = module.UTF8ToString(module._jostle_version());
    this.page = new JostlePage(this);
    // The module's memory where jostle.js lays out the structs of jostle.h's calls (at
    // Jostle.HANDLE, VECTOR and OUT), and the buffer of boxes()'s reads, grown as needed.
    this.scratch = module._malloc(Jostle.SCRATCH);
    this.buffer = 0;
    this.bufferSize = 0;
  }

  // A struct of jostle.h goes through WebAssembly's C calls by address: an argument
  // (jostle_body_id, jostle_vec2) as a pointer to its bytes, a result as a pointer, put
  // first, to the bytes it is written to. Their places in the scratch memory, in bytes:
  static HANDLE = 0; // a jostle_body_id or jostle_tile_map_id: index, generation, world
  static VECTOR = 12; // a jostle_vec2 argument: x, y
  static OUT = 20; // the results of body(): position, velocity (jostle_vec2), touching
  static SCRATCH = 64;

  /// A world from a scene: an object or a scene file's text. Its bodies, if any, are
  /// numbered from 0 in their order.
  createWorld(scene = {}) {
    const fn = "createWorld";
    if (typeof scene !== "string")
      if (typeof scene !== "object" || scene === null || Array.isArray(scene))
        throw new TypeError(`${fn}: scene must be an object or a scene file's text, got ${JostleArgs.describe(scene)}`);
    const text = typeof scene === "string" ? scene : JostleArgs.json(fn, {bodies: [], ...scene});
    const m = this.module;
    // The scene loader reads the text into jostle.h's definitions (web_c_api.cpp), which
    // jostle.h's functions then create, as a C program would.
    const def = this.withText(text, (p) => m._jostle_web_read_scene(p));
    this.check(fn, def !== 0);
    try {
      const pointer = m._jostle_world_create(def);
      this.check(fn, pointer !== 0);
      const world = new JostleWorld(this, pointer);
      try {
        for (let i = 0, map; (map = m._jostle_web_scene_tile_map(i)) !== 0; i++) {
          m._jostle_tile_map_create(this.scratch + Jostle.HANDLE, pointer, map);
          this.check(fn, m.HEAPU32[(this.scratch + Jostle.HANDLE) / 4 + 1] !== 0);
        }
        for (let i = 0, body; (body = m._jostle_web_scene_body(i)) !== 0; i++) {
          m._jostle_body_create(this.scratch + Jostle.HANDLE, pointer, body);
          world.created(fn);
        }
      } catch (error) {
        m._jostle_world_destroy(pointer);
        throw error;
      }
      return world;
    } finally {
      m._jostle_web_forget_scene();
    }
  }

  // --- Between JavaScript and the module --------------------------------------------

  /// Does nothing if `ok`: a call of jostle.h (or web_c_api.cpp) said it did what was
  /// asked (true, a pointer, a handle that is not null). Else throws its error, the C
  /// API's last error in JavaScript's notation, named by the function `fn` where the C
  /// function's name was ("jostle_body_set_velocity: setVelocity: a static body cannot
  /// move" becomes "setVelocity: a static body cannot move", "jostle_web_read_body: hw:
  /// must be > 0" "createBody: hw: must be > 0").
  check(fn, ok) {
    if (ok) return;
    let message = this.text(this.module._jostle_web_last_error());
    const cFunction = /^jostle_\w+: /.exec(message);
    if (cFunction !== null) message = message.slice(cFunction[0].length);
    throw new Error(message.startsWith(`${fn}: `) ? message : `${fn}: ${message}`);
  }

  /// Calls fn with a pointer to `text` in the module's memory, as UTF-8; frees it after.
  withText(text, fn) {
    const m = this.module;
    const size = m.lengthBytesUTF8(text) + 1;
    const pointer = m._malloc(size);
    try {
      m.stringToUTF8(text, pointer, size);
      return fn(pointer);
    } finally {
      m._free(pointer);
    }
  }

  text(pointer) {
    return this.module.UTF8ToString(pointer);
  }

  /// `count` floats at `pointer`, copied: the module's memory may grow and move.
  floats(pointer, count) {
    return this.module.HEAPF32.slice(pointer / 4, pointer / 4 + count);
  }

  /// The address of a jostle_vec2 {x, y} in the scratch memory.
  vector(x, y) {
    const at = this.scratch + Jostle.VECTOR, floats = this.module.HEAPF32;
    floats[at / 4] = x;
    floats[at / 4 + 1] = y;
    return at;
  }

  /// A buffer of at least `size` bytes in the module's memory, kept for the next call.
  bufferOf(size) {
    if (size > this.bufferSize) {
      this.module._free(this.buffer);
      this.bufferSize = Math.max(size, 2 * this.bufferSize, 1024);
      this.buffer = this.module._malloc(this.bufferSize);
    }
    return this.buffer;
  }
}

/// A world of a game, over jostle.h's jostle_world. Bodies are numbers: a number names its
/// body until the body is destroyed; then it is refused until createBody gives it again,
/// to a new body.
class JostleWorld {
  constructor(jostle, pointer) {
    this.jostle = jostle;
    this.pointer = pointer; // the jostle_world*; null once destroyed
    // Body numbers: the handle (jostle_body_id) of number n is {slots[n],
    // generations[n], serial}, slots[n] -1 where no live body has n; the numbers below
    // slots.length that no live body has, smallest first; a slot's number, for boxes().
    this.slots = [];
    this.generations = [];
    this.serial = 0; // the world's, which its handles carry
    this.free = new JostleFreeNumbers();
    this.numberOfSlot = [];
    // The numbers' tables of each snapshot this world took, for its restore.
    this.numbering = new WeakMap();
  }

  /// A body from a scene file's body object: {type, x, y, hw, hh, vx, vy, bounce, ...}.
  /// Returns its number: the smallest that no live body of the world has.
  createBody(def) {
    const fn = "createBody";
    const text = JostleArgs.json(fn, JostleArgs.object(fn, "def", def));
    const world = this.live(fn);
    const j = this.jostle, m = j.module;
    const read = j.withText(text, (p) => m._jostle_web_read_body(world, p));
    j.check(fn, read !== 0);
    m._jostle_body_create(j.scratch + Jostle.HANDLE, world, read);
    return this.created(fn);
  }

  /// Removes a body; its number may be given to a later body.
  destroyBody(body) {
    const fn = "destroyBody";
    JostleArgs.body(fn, body);
    const world = this.live(fn);
    this.jostle.check(fn, this.jostle.module._jostle_body_destroy(world, this.handle(fn, body)) !== 0);
    this.numberOfSlot[this.slots[body]] = -1;
    this.slots[body] = -1;
    this.free.push(body);
  }

  step(dt) {
    const fn = "step";
    JostleArgs.number(fn, "dt", dt);
    this.jostle.check(fn, this.jostle.module._jostle_world_step(this.live(fn), dt) !== 0);
  }

  /// Every body that exists, in creation order: {body, x, y, hw, hh} (centre and half
  /// extents). Costs as much as the live bodies, whatever the world made before: three
  /// calls read every body's handle, position and half extents.
  boxes() {
    const world = this.live("boxes");
    const j = this.jostle, m = j.module;
    const count = m._jostle_world_body_count(world);
    // 12 bytes a handle, 8 a position, 8 half extents.
    const ids = j.bufferOf(28 * count), positions = ids + 12 * count, halves = ids + 20 * count;
    m._jostle_world_bodies(world, ids, count);
    m._jostle_world_read_positions(world, positions, count);
    m._jostle_world_read_half_extents(world, halves, count);
    // Read at once: the memory does not move before the module is called again.
    const words = m.HEAPU32, floats = m.HEAPF32;
    const boxes = [];
    for (let i = 0, id = ids / 4, p = positions / 4, h = halves / 4; i < count; i++, id += 3, p += 2, h += 2) {
      // A tile map's body has no number.
      const body = this.numberOfSlot[words[id]];
      if (body === undefined || body < 0 || this.generations[body] !== words[id + 1]) continue;
      boxes.push({body, x: floats[p], y: floats[p + 1], hw: floats[h], hh: floats[h + 1]});
    }
    return boxes;
  }

  /// One body: its centre, velocity, and the sides it touched in the last step.
  body(body) {
    const fn = "body";
    JostleArgs.body(fn, body);
    const world = this.live(fn);
    const m = this.jostle.module, handle = this.handle(fn, body), out = this.jostle.scratch + Jostle.OUT;
    m._jostle_body_get_position(out, world, handle);
    m._jostle_body_get_velocity(out + 8, world, handle);
    m._jostle_body_get_touching(out + 16, world, handle); // four bools
    const floats = m.HEAPF32, bytes = m.HEAPU8, at = out / 4;
    return {x: floats[at], y: floats[at + 1], vx: floats[at + 2], vy: floats[at + 3],
            touching: {floor: bytes[out + 16] !== 0, ceiling: bytes[out + 17] !== 0,
                       wallLeft: bytes[out + 18] !== 0, wallRight: bytes[out + 19] !== 0}};
  }

  /// A body's definition as a scene file's body object: its type, centre, size,
  /// velocity and every setting as it is now ({type, x, y, hw, hh, vx, vy, bounce, ...};
  /// mass or density, the one in use), ready to change and give to createBody.
  bodyDef(body) {
    const fn = "bodyDef";
    JostleArgs.body(fn, body);
    const world = this.live(fn), j = this.jostle;
    const text = j.module._jostle_web_body_def(world, this.handle(fn, body));
    j.check(fn, text !== 0);
    return JSON.parse(j.text(text));
  }

  setVelocity(body, vx, vy) { this.withBody("setVelocity", "_jostle_body_set_velocity", body, {vx, vy}); }
  setPosition(body, x, y) { this.withBody("setPosition", "_jostle_body_set_position", body, {x, y}); }
  applyImpulse(body, ix, iy) { this.withBody("applyImpulse", "_jostle_body_apply_impulse", body, {ix, iy}); }
  /// A character's speed along what it stands on (docs/characters.md).
  setWalkSpeed(body, speed) { this.withBody("setWalkSpeed", "_jostle_body_set_walk_speed", body, {speed}); }
  /// Falls through one-way platforms for `seconds`.
  dropThrough(body, seconds) { this.withBody("dropThrough", "_jostle_body_drop_through", body, {seconds}); }

  // --- Snapshots (docs/snapshots.md) -------------------------------------------------

  /// A snapshot of the whole world: the bytes C and C++ write, in a Uint8Array of its own.
  snapshot() {
    const fn = "snapshot";
    const world = this.live(fn);
    const j = this.jostle, m = j.module;
    // Written into the buffer as it is, in one pass; only when it is too small (the first
    // snapshot, a world that grew) is the size asked for, which costs a second pass.
    let at = j.bufferOf(1), size = m._jostle_world_snapshot(world, at, j.bufferSize);
    if (size === 0) {
      const needed = m._jostle_world_snapshot_size(world);
      j.check(fn, needed !== 0);
      at = j.bufferOf(needed);
      size = m._jostle_world_snapshot(world, at, needed);
      j.check(fn, size === needed);
    }
    const bytes = m.HEAPU8.slice(at, at + size);
    this.numbering.set(bytes, this.numbers());
    return bytes;
  }

  /// Makes the world what it was when `bytes` were taken. Body numbers are as they were
  /// then for a snapshot this world took; for one from elsewhere (a peer's), the live
  /// bodies but tile maps' are numbered 0, 1, 2... in creation order.
  restore(bytes) {
    const fn = "restore";
    if (!(bytes instanceof Uint8Array))
      throw new TypeError(`${fn}: snapshot must be a Uint8Array (from snapshot()), got ${JostleArgs.describe(bytes)}`);
    const world = this.live(fn);
    const j = this.jostle, m = j.module;
    const at = j.bufferOf(bytes.length);
    m.HEAPU8.set(bytes, at);
    j.check(fn, m._jostle_world_restore(world, at, bytes.length) !== 0);
    const numbers = this.numbering.get(bytes);
    if (numbers !== undefined) this.setNumbers(numbers);
    else this.numberInCreationOrder();
  }

  /// A hash of exactly what a snapshot holds, as 16 hexadecimal digits: peers whose
  /// worlds are the same, bit for bit, have the same.
  stateHash() {
    const fn = "stateHash";
    const hash = this.jostle.text(this.jostle.module._jostle_web_state_hash(this.live(fn)));
    this.jostle.check(fn, hash !== "");
    return hash;
  }

  /// The body numbers' tables, copied.
  numbers() {
    return {slots: this.slots.slice(), generations: this.generations.slice(),
            free: this.free.heap.slice(), numberOfSlot: this.numberOfSlot.slice()};
  }

  setNumbers(numbers) {
    this.slots = numbers.slots.slice();
    this.generations = numbers.generations.slice();
    this.free.heap = numbers.free.slice();
    this.numberOfSlot = numbers.numberOfSlot.slice();
  }

  numberInCreationOrder() {
    const world = this.pointer, j = this.jostle, m = j.module;
    const count = m._jostle_world_body_count(world);
    const ids = j.bufferOf(12 * count + 12);
    m._jostle_world_bodies(world, ids, count);
    this.setNumbers({slots: [], generations: [], free: [], numberOfSlot: []});
    for (let i = 0; i < count; i++) {
      const handle = ids + 12 * i;
      m._jostle_tile_map_of(ids + 12 * count, world, handle); // a jostle_tile_map_id
      const words = m.HEAPU32;
      if (words[(ids + 12 * count) / 4 + 1] !== 0) continue; // a tile map's
      const body = this.slots.length;
      this.slots[body] = words[handle / 4];
      this.generations[body] = words[handle / 4 + 1];
      this.serial = words[handle / 4 + 2];
      this.numberOfSlot[this.slots[body]] = body;
    }
  }

  /// Frees the world; it may not be used after.
  destroy() {
    const fn = "destroy";
    this.jostle.check(fn, this.jostle.module._jostle_world_destroy(this.live(fn)) !== 0);
    this.pointer = null;
  }

  /// The world's jostle_world*, or an Error if it was destroyed (another world may have
  /// its memory now).
  live(fn) {
    if (this.pointer === null) throw new Error(`${fn}: the world was destroyed`);
    return this.pointer;
  }

  /// The address of the handle of body number `body` (checked by JostleArgs.body), laid
  /// out in the scratch memory; or an Error if no live body has the number.
  handle(fn, body) {
    const slot = this.slots[body];
    if (slot === undefined || slot < 0) throw new Error(`${fn}: no such body: ${body}`);
    const at = this.jostle.scratch + Jostle.HANDLE, words = this.jostle.module.HEAPU32;
    words[at / 4] = slot;
    words[at / 4 + 1] = this.generations[body];
    words[at / 4 + 2] = this.serial;
    return at;
  }

  /// Gives the body whose handle jostle_body_create just wrote to the scratch memory the
  /// smallest number no live body has, and returns it; or throws the error of a null
  /// handle.
  created(fn) {
    const at = (this.jostle.scratch + Jostle.HANDLE) / 4;
    const [slot, generation, serial] = this.jostle.module.HEAPU32.subarray(at, at + 3);
    this.jostle.check(fn, generation !== 0);
    const body = this.free.size > 0 ? this.free.pop() : this.slots.length;
    this.slots[body] = slot;
    this.generations[body] = generation;
    this.serial = serial;
    this.numberOfSlot[slot] = body;
    return body;
  }

  /// Calls `name` of jostle.h with the world, the handle of `body` and `numbers` ({name:
  /// value}, in order), each checked: a pair is a jostle_vec2, one number a float.
  withBody(fn, name, body, numbers) {
    JostleArgs.body(fn, body);
    const values = Object.entries(numbers).map(([argument, value]) => JostleArgs.number(fn, argument, value));
    const world = this.live(fn);
    const j = this.jostle, handle = this.handle(fn, body);
    const argument = values.length === 2 ? j.vector(values[0], values[1]) : values[0];
    j.check(fn, j.module[name](world, handle, argument) !== 0);
  }
}

/// The numbers no live body of a world has, below the largest given: a binary heap, so
/// that the smallest is taken first, each push and pop in time logarithmic in the count.
class JostleFreeNumbers {
  constructor() {
    this.heap = [];
  }

  get size() {
    return this.heap.length;
  }

  push(number) {
    const heap = this.heap;
    let i = heap.push(number) - 1;
    while (i > 0 && heap[(i - 1) >> 1] > number) {
      heap[i] = heap[(i - 1) >> 1];
      i = (i - 1) >> 1;
    }
    heap[i] = number;
  }

  /// The smallest, taken out.
  pop() {
    const heap = this.heap, smallest = heap[0], last = heap.pop();
    if (heap.length > 0) {
      let i = 0;
      for (;;) {
        let child = 2 * i + 1;
        if (child >= heap.length) break;
        if (child + 1 < heap.length && heap[child + 1] < heap[child]) child++;
        if (heap[child] >= last) break;
        heap[i] = heap[child];
        i = child;
      }
      heap[i] = last;
    }
    return smallest;
  }
}

/// The demo's samples (demo/sample_*.cpp), for the page: one current sample, its panes
/// (worlds side by side), the keys and the mouse.
class JostlePage {
  static KEYS = {left: 1, right: 2, up: 4, down: 8, jump: 16};

  constructor(jostle) {
    this.jostle = jostle;
    this.m = jostle.module;
  }

  sampleNames() {
    const names = [];
    for (let i = 0; i < this.m._jostle_page_sample_count(); i++)
      names.push(this.jostle.text(this.m._jostle_page_sample_name(i)));
    return names;
  }

  select(index) { return this.m._jostle_page_select(index) !== 0; }
  reset() { this.m._jostle_page_reset(); }
  currentName() { return this.jostle.text(this.m._jostle_page_current_name()); }
  usesLetterKeys() { return this.m._jostle_page_uses_letter_keys() !== 0; }

  /// Loads a scene file's text as the current sample; throws the loader's message.
  loadScene(text) {
    const error = this.jostle.text(this.jostle.withText(text, (p) =>
      this.m._jostle_page_load_scene(p)));
    if (error !== "") throw new Error(error);
  }

  /// One step of every pane with the keys held (bits of JostlePage.KEYS); returns the
  /// milliseconds the worlds' steps took.
  step(keys, dt) { return this.m._jostle_page_step(keys, dt); }

  paneCount() { return this.m._jostle_page_pane_count(); }
  paneTitle(pane) { return this.jostle.text(this.m._jostle_page_pane_title(pane)); }
  paneModel(pane) { return this.jostle.text(this.m._jostle_page_pane_model(pane)); }

  /// The box of the world a pane shows: {minX, minY, maxX, maxY}.
  view(pane) {
    const [minX, minY, maxX, maxY] = this.read("_jostle_page_read_view", 4, pane);
    return {minX, minY, maxX, maxY};
  }

  bodyCount(pane) { return this.m._jostle_page_body_count(pane); }
  /// Every body of a pane: 12 floats each, as jostle_page_read_bodies (page_api.cpp).
  bodies(pane) { return this.read("_jostle_page_read_bodies", 12, pane); }
  /// The touching pairs: point x, y, normal x, y, extent (jostle_page_read_contacts).
  contacts(pane) { return this.read("_jostle_page_read_contacts", 5, pane); }

  /// The picture of a pane's broadphase grid (demo/grid_picture.hpp) for steps of `dt`:
  /// {name, mainLevel, levelZero, inMainLevel, boxes: [{minX, minY, maxX, maxY, growX,
  /// growY, level}]}; level k's cells are levelZero × 2^k, the last level (63) infinite.
  grid(pane, dt) {
    const count = this.m._jostle_page_read_grid(pane, dt);
    const data = this.jostle.floats(this.m._jostle_page_data(), 3 + 7 * count);
    const boxes = [];
    for (let i = 0; i < count; i++) {
      const [minX, minY, maxX, maxY, growX, growY, level] = data.subarray(3 + 7 * i, 10 + 7 * i);
      boxes.push({minX, minY, maxX, maxY, growX, growY, level});
    }
    return {name: this.jostle.text(this.m._jostle_page_grid_name()), mainLevel: data[0],
            levelZero: data[1], inMainLevel: data[2], boxes};
  }

  /// The labels of a pane: {text, x, y, hw, hh} of the body each is drawn above.
  labels(pane) {
    const data = this.read("_jostle_page_read_labels", 4, pane);
    const labels = [];
    for (let i = 0; 4 * i < data.length; i++) {
      const [x, y, hw, hh] = data.subarray(4 * i, 4 * i + 4);
      labels.push({text: this.jostle.text(this.m._jostle_page_label_text(pane, i)), x, y, hw, hh});
    }
    return labels;
  }

  /// The character the keys steer: {x, y, vx, vy, floor}, or null.
  player() {
    const data = this.read("_jostle_page_read_player", 5);
    if (data.length === 0) return null;
    const [x, y, vx, vy, floor] = data;
    return {x, y, vx, vy, floor: floor !== 0};
  }

  /// The mouse, in world units of a pane.
  grab(pane, x, y) { return this.m._jostle_page_grab(pane, x, y) !== 0; }
  dragTo(x, y) { this.m._jostle_page_drag_to(x, y); }
  release() { this.m._jostle_page_release(); }
  dropBox(pane, x, y, half) { this.m._jostle_page_drop_box(pane, x, y, half); }

  /// Sample `index` run without a window for the check (sample_check.hpp): its hash, in
  /// decimal, which jostle-web-sample-hashes prints natively.
  check(index) { return this.jostle.text(this.m._jostle_page_check(index)); }

  read(name, per, ...args) {
    const count = this.m[name](...args);
    return this.jostle.floats(this.m._jostle_page_data(), per * count);
  }
}
