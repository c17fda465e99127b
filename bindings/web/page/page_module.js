// The page's layer over the npm package (docs/web.md): the package's API over the page's
// module, which is the game module with the demo's samples and their C surface
// (page_api.cpp) beside it; and JostlePage, which drives the samples. esbuild bundles this
// file with the package's sources and the module's loader into jostle-page.mjs.
//
//     const {jostle, page} = await loadPage();   // jostle: the package's Jostle
import {load} from "../package/src/index.js";
import {colourAt, drawCalls} from "../package/src/world.js";

/// The package over the page's module (jostle-web.wasm, beside the bundle), and its samples.
export async function loadPage() {
  const jostle = await load({wasm: new URL("./jostle-web.wasm", import.meta.url)});
  return {jostle, page: new JostlePage(jostle)};
}

/// The demo's samples (demo/sample_*.cpp), for the page: one current sample, its panes
/// (worlds side by side), the keys and the mouse.
export class JostlePage {
  static KEYS = {left: 1, right: 2, up: 4, down: 8, jump: 16};

  constructor(jostle) {
    this.rt = jostle.rt;
    this.m = jostle.rt.m;
  }

  sampleNames() {
    const names = [];
    for (let i = 0; i < this.m._jostle_page_sample_count(); i++)
      names.push(this.rt.text(this.m._jostle_page_sample_name(i)));
    return names;
  }

  select(index) { return this.m._jostle_page_select(index) !== 0; }
  reset() { this.m._jostle_page_reset(); }
  currentName() { return this.rt.text(this.m._jostle_page_current_name()); }
  usesLetterKeys() { return this.m._jostle_page_uses_letter_keys() !== 0; }

  /// Loads a scene file's text as the current sample; throws the loader's message.
  loadScene(text) {
    const error = this.rt.text(this.rt.withText(text, (p) =>
      this.m._jostle_page_load_scene(p)));
    if (error !== "") throw new Error(error);
  }

  /// One step of every pane with the keys held (bits of JostlePage.KEYS); returns the
  /// milliseconds the worlds' steps took.
  step(keys, dt) { return this.m._jostle_page_step(keys, dt); }

  paneCount() { return this.m._jostle_page_pane_count(); }
  paneTitle(pane) { return this.rt.text(this.m._jostle_page_pane_title(pane)); }
  paneModel(pane) { return this.rt.text(this.m._jostle_page_pane_model(pane)); }

  /// The box of the world a pane shows: {minX, minY, maxX, maxY}.
  view(pane) {
    const [minX, minY, maxX, maxY] = this.read("_jostle_page_read_view", 4, pane);
    return {minX, minY, maxX, maxY};
  }

  bodyCount(pane) { return this.m._jostle_page_body_count(pane); }
  /// Every body of a pane: 12 floats each, as jostle_page_read_bodies (page_api.cpp).
  bodies(pane) { return this.read("_jostle_page_read_bodies", 12, pane); }
  /// Draws a pane's world through `draw` as world.debugDraw does (docs/debug-draw.md): with
  /// `debug`, its contacts, velocities, touched sides and broadphase cells too; marks
  /// `markLength` long; what touches `view` ({minX, minY, maxX, maxY}) only.
  debugDraw(pane, draw, debug, markLength, view) {
    const count = this.m._jostle_page_debug_draw(pane, debug, markLength, view.minX, view.minY,
                                                 view.maxX, view.maxY);
    drawCalls(this.m, this.m._jostle_page_draw_calls(), count, draw);
  }

  /// The library's debug-draw colours (jostle::DebugPalette) as 0xRRGGBBAA, by their names
  /// in JavaScript, and its two percentages: for a legend of what the marks mean.
  palette() {
    const rt = this.rt, m = this.m, L = rt.layout.debug_palette;
    const at = rt.debugDrawOptions("palette") + rt.layout.debug_draw_options.palette;
    const palette = {};
    for (const name of Object.keys(L)) {
      if (name === "size") continue;
      const key = name.replace(/_(.)/g, (_, c) => c.toUpperCase()), p = at + L[name];
      palette[key] = name.endsWith("percent") ? m.HEAP32[p >> 2] : colourAt(m.HEAPU8, p);
    }
    return palette;
  }

  /// The picture of a pane's broadphase grid (demo/grid_picture.hpp) for steps of `dt`:
  /// {name, mainLevel, levelZero, inMainLevel, boxes: [{minX, minY, maxX, maxY, growX,
  /// growY, level}]}; level k's cells are levelZero × 2^k, the last level (63) infinite.
  grid(pane, dt) {
    const count = this.m._jostle_page_read_grid(pane, dt);
    const data = this.floats(this.m._jostle_page_data(), 3 + 7 * count);
    const boxes = [];
    for (let i = 0; i < count; i++) {
      const [minX, minY, maxX, maxY, growX, growY, level] = data.subarray(3 + 7 * i, 10 + 7 * i);
      boxes.push({minX, minY, maxX, maxY, growX, growY, level});
    }
    return {name: this.rt.text(this.m._jostle_page_grid_name()), mainLevel: data[0],
            levelZero: data[1], inMainLevel: data[2], boxes};
  }

  /// The labels of a pane: {text, x, y, hw, hh} of the body each is drawn above.
  labels(pane) {
    const data = this.read("_jostle_page_read_labels", 4, pane);
    const labels = [];
    for (let i = 0; 4 * i < data.length; i++) {
      const [x, y, hw, hh] = data.subarray(4 * i, 4 * i + 4);
      labels.push({text: this.rt.text(this.m._jostle_page_label_text(pane, i)), x, y, hw, hh});
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
  check(index) { return this.rt.text(this.m._jostle_page_check(index)); }

  /// `count` floats at `pointer`, copied: the module's memory may grow and move.
  floats(pointer, count) {
    return this.m.HEAPF32.slice(pointer / 4, pointer / 4 + count);
  }

  read(name, per, ...args) {
    const count = this.m[name](...args);
    return this.floats(this.m._jostle_page_data(), per * count);
  }
}
