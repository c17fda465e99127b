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
// as they are: a mistake throws an Error naming the field. `jostle.page` drives the demo's
// samples, for the page itself (page.js).
"use strict";

class Jostle {
  /// Loads the module; `options` go to emscripten's factory (locateFile, say).
  static async load(options = {}) {
    return new Jostle(await createJostleModule(options));
  }

  constructor(module) {
    this.module = module;
    this.page = new JostlePage(this);
  }

  /// A world from a scene: an object or a scene file's text. Its bodies, if any, are
  /// numbered from 0 in their order.
  createWorld(scene = {}) {
    const text = typeof scene === "string" ? scene : JSON.stringify({bodies: [], ...scene});
    const number = this.withText(text, (p) => this.module._jostle_game_world_create(p));
    this.check(number >= 0);
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

  /// Throws the module's last error unless `ok`.
  check(ok) {
    if (!ok) throw new Error(this.text(this.module._jostle_game_error()));
  }
}

/// A world of a game. Bodies are numbers; a destroyed body's number is not reused.
class JostleWorld {
  constructor(jostle, number) {
    this.jostle = jostle;
    this.number = number;
  }

  /// A body from a scene file's body object: {type, x, y, hw, hh, vx, vy, bounce, ...}.
  createBody(def) {
    const j = this.jostle;
    const body = j.withText(JSON.stringify(def), (p) =>
      j.module._jostle_game_body_create(this.number, p));
    j.check(body >= 0);
    return body;
  }

  destroyBody(body) {
    this.call("_jostle_game_body_destroy", body);
  }

  step(dt) {
    this.call("_jostle_game_step", dt);
  }

  /// Every body that exists: {body, x, y, hw, hh} (centre and half extents).
  boxes() {
    const j = this.jostle;
    const count = j.module._jostle_game_read_boxes(this.number);
    j.check(count >= 0);
    const data = j.floats(j.module._jostle_game_data(), 5 * count);
    const boxes = [];
    for (let i = 0; i < count; i++) {
      const [body, x, y, hw, hh] = data.subarray(5 * i, 5 * i + 5);
      boxes.push({body, x, y, hw, hh});
    }
    return boxes;
  }

  /// One body: its centre, velocity, and the sides it touched in the last step.
  body(body) {
    const j = this.jostle;
    j.check(j.module._jostle_game_read_body(this.number, body) >= 0);
    const [x, y, vx, vy, t] = j.floats(j.module._jostle_game_data(), 5);
    return {x, y, vx, vy, touching: {floor: (t & 1) !== 0, ceiling: (t & 2) !== 0,
                                      wallLeft: (t & 4) !== 0, wallRight: (t & 8) !== 0}};
  }

  setVelocity(body, vx, vy) { this.call("_jostle_game_set_velocity", body, vx, vy); }
  setPosition(body, x, y) { this.call("_jostle_game_set_position", body, x, y); }
  applyImpulse(body, ix, iy) { this.call("_jostle_game_apply_impulse", body, ix, iy); }
  /// A character's speed along what it stands on (docs/characters.md).
  setWalkSpeed(body, speed) { this.call("_jostle_game_set_walk_speed", body, speed); }
  /// Falls through one-way platforms for `seconds`.
  dropThrough(body, seconds) { this.call("_jostle_game_drop_through", body, seconds); }

  /// Frees the world; it may not be used after.
  destroy() {
    this.call("_jostle_game_world_destroy");
  }

  call(name, ...args) {
    this.jostle.check(this.jostle.module[name](this.number, ...args));
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
