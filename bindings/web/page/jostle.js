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
// Worlds and bodies are described as in scene files (docs/scene-format.md), and checked
// as they are: a mistake throws an Error naming the field. Every argument is checked
// before it reaches the module (JostleArgs): a wrong kind throws a TypeError naming the
// function and the argument. `jostle.page` drives the demo's samples, for the page
// itself (page.js).
"use strict";

/// The checks of the arguments a game passes, made before anything reaches the module:
/// each throws a TypeError that names the function, the argument and what it got. What
/// only the module knows (whether a body is alive, jostle's own rules: dt > 0, a static
/// body does not move, a definition's fields) it reports itself, as an Error that names
/// the function too.
class JostleArgs {
  /// A body number: an integer >= 0. Returns it. (Whether a body has it is the module's
  /// to say: "no such body: 3". A number past the int32 the module takes can name none.)
  static body(fn, value) {
    if (typeof value !== "number" || !Number.isInteger(value) || value < 0)
      throw new TypeError(`${fn}: body must be a body number (an integer >= 0), got ${JostleArgs.describe(value)}`);
    if (value > 0x7fffffff) throw new Error(`${fn}: no such body: ${value}`);
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
    this.page = new JostlePage(this);
  }

  /// A world from a scene: an object or a scene file's text. Its bodies, if any, are
  /// numbered from 0 in their order.
  createWorld(scene = {}) {
    const fn = "createWorld";
    if (typeof scene !== "string")
      if (typeof scene !== "object" || scene === null || Array.isArray(scene))
        throw new TypeError(`${fn}: scene must be an object or a scene file's text, got ${JostleArgs.describe(scene)}`);
    const text = typeof scene === "string" ? scene : JostleArgs.json(fn, {bodies: [], ...scene});
    const number = this.withText(text, (p) => this.module._jostle_game_world_create(p));
    this.check(fn, number);
    return new JostleWorld(this, number);
  }

  // --- Between JavaScript and the module's memory -----------------------------------

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

  /// Returns `result`, what a call of the game's surface returned, or throws its error,
  /// which it reported with -1, named by the function `fn`.
  check(fn, result) {
    if (result >= 0) return result;
    const message = this.text(this.module._jostle_game_error());
    throw new Error(message.startsWith(`${fn}: `) ? message : `${fn}: ${message}`);
  }
}

/// A world of a game. Bodies are numbers: a number names its body until the body is
/// destroyed; then it is refused until createBody gives it again, to a new body.
class JostleWorld {
  constructor(jostle, number) {
    this.jostle = jostle;
    this.number = number; // null once destroyed
  }

  /// A body from a scene file's body object: {type, x, y, hw, hh, vx, vy, bounce, ...}.
  /// Returns its number: the smallest that no live body of the world has.
  createBody(def) {
    const fn = "createBody";
    const text = JostleArgs.json(fn, JostleArgs.object(fn, "def", def));
    const world = this.live(fn);
    const j = this.jostle;
    return j.check(fn, j.withText(text, (p) => j.module._jostle_game_body_create(world, p)));
  }

  /// Removes a body; its number may be given to a later body.
  destroyBody(body) {
    const fn = "destroyBody";
    this.call(fn, "_jostle_game_body_destroy", JostleArgs.body(fn, body));
  }

  step(dt) {
    const fn = "step";
    this.call(fn, "_jostle_game_step", JostleArgs.number(fn, "dt", dt));
  }

  /// Every body that exists, in creation order: {body, x, y, hw, hh} (centre and half
  /// extents). Costs as much as the live bodies, whatever the world made before.
  boxes() {
    const m = this.jostle.module;
    const count = this.call("boxes", "_jostle_game_read_boxes");
    // Five 32-bit words a body: its number (an int32, exact) and four floats. Read at
    // once: the memory does not move before the module is called again.
    const at = m._jostle_game_boxes() / 4;
    const ints = m.HEAP32, floats = m.HEAPF32;
    const boxes = new Array(count);
    for (let i = 0, w = at; i < count; i++, w += 5)
      boxes[i] = {body: ints[w], x: floats[w + 1], y: floats[w + 2], hw: floats[w + 3], hh: floats[w + 4]};
    return boxes;
  }

  /// One body: its centre, velocity, and the sides it touched in the last step.
  body(body) {
    const fn = "body";
    const j = this.jostle;
    this.call(fn, "_jostle_game_read_body", JostleArgs.body(fn, body));
    const [x, y, vx, vy, t] = j.floats(j.module._jostle_game_data(), 5);
    return {x, y, vx, vy, touching: {floor: (t & 1) !== 0, ceiling: (t & 2) !== 0,
                                      wallLeft: (t & 4) !== 0, wallRight: (t & 8) !== 0}};
  }

  setVelocity(body, vx, vy) { this.withBody("setVelocity", "_jostle_game_set_velocity", body, {vx, vy}); }
  setPosition(body, x, y) { this.withBody("setPosition", "_jostle_game_set_position", body, {x, y}); }
  applyImpulse(body, ix, iy) { this.withBody("applyImpulse", "_jostle_game_apply_impulse", body, {ix, iy}); }
  /// A character's speed along what it stands on (docs/characters.md).
  setWalkSpeed(body, speed) { this.withBody("setWalkSpeed", "_jostle_game_set_walk_speed", body, {speed}); }
  /// Falls through one-way platforms for `seconds`.
  dropThrough(body, seconds) { this.withBody("dropThrough", "_jostle_game_drop_through", body, {seconds}); }

  /// Frees the world; it may not be used after.
  destroy() {
    this.call("destroy", "_jostle_game_world_destroy");
    this.number = null;
  }

  /// The world's number, or an Error if it was destroyed (its number may be another's now).
  live(fn) {
    if (this.number === null) throw new Error(`${fn}: the world was destroyed`);
    return this.number;
  }

  /// Calls `name` of the module with a body and `numbers` ({name: value}, in order),
  /// each checked.
  withBody(fn, name, body, numbers) {
    JostleArgs.body(fn, body);
    for (const [argument, value] of Object.entries(numbers)) JostleArgs.number(fn, argument, value);
    this.call(fn, name, body, ...Object.values(numbers));
  }

  /// Calls `name` of the module for this world with `args`, checked already; returns
  /// what it returned, or throws its error.
  call(fn, name, ...args) {
    const world = this.live(fn);
    return this.jostle.check(fn, this.jostle.module[name](world, ...args));
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
