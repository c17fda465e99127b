// Between JavaScript and the module: jostle.h's functions called as a C program calls
// them, its structs laid out where the compiler put their members (jostle_web_layout), and
// its error contract turned into exceptions.
//
// A struct goes through WebAssembly's C calls by address: an argument (a body's handle, a
// vector) as a pointer to its bytes, a result as a pointer, put first, to the bytes it is
// written to. Both live in a scratch block of the module's memory, at these places:
const HANDLE = 0; // a jostle_body_id or jostle_tile_map_id argument: index, generation, world
const OTHER = 16; // a second handle
const VECTORS = 32; // three jostle_vec2 arguments, 8 bytes each
const FILTER = 56; // a jostle_query_filter
const OUT = 96; // a result: a struct, a vector, two ints...
const SCRATCH = 256;

import * as args from "./args.js";

/// camelCase as jostle.h's snake_case: markLength is mark_length.
const snake = (name) => name.replace(/[A-Z]/g, (c) => `_${c.toLowerCase()}`);

export class Runtime {
  constructor(module) {
    this.m = module;
    this.layout = JSON.parse(module.UTF8ToString(module._jostle_web_layout()));
    this.scratch = module._malloc(SCRATCH);
    this.out = this.scratch + OUT;
    // A buffer for reads of many things (bodies, events, hits), grown as needed.
    this.buffer = 0;
    this.bufferSize = 0;
    this.drawOptions = 0; // a jostle_debug_draw_options, made on first use
    this.drawing = false; // while debugDraw makes the game's calls
  }

  // --- Errors -----------------------------------------------------------------------------

  /// Does nothing if `ok`: the call of jostle.h said it did what was asked (true, a
  /// pointer, a handle that is not null). Else throws its error, the C API's last error
  /// in JavaScript's notation, named by the method `fn` where the C function's name was
  /// ("jostle_body_set_velocity: a static body cannot move" becomes "setVelocity: a
  /// static body cannot move"), and clears it: a failed call is the last error's only
  /// source, so that a getter's zero is an answer unless an error stands (failed()).
  /// `cppName`: the C++ function's name, where it is not the method's.
  check(fn, ok, cppName = null) {
    if (ok) return;
    let message = this.m.UTF8ToString(this.m._jostle_web_last_error());
    this.m._jostle_clear_error();
    const cFunction = /^jostle_\w+: /.exec(message);
    if (cFunction !== null) message = message.slice(cFunction[0].length);
    // A property's C++ setter names itself: "setFriction: ..." is friction's; so does a
    // method's C++ function where the names differ ("destroyBody: ..." is destroy's).
    for (const named of [`set${fn[0].toUpperCase()}${fn.slice(1)}: `, cppName && `${cppName}: `])
      if (named && message.startsWith(named)) message = message.slice(named.length);
    throw new Error(message.startsWith(`${fn}: `) ? message : `${fn}: ${message}`);
  }

  /// True if the last call of jostle.h failed (its result is then the zero of its type).
  failed() {
    return this.m.HEAPU8[this.m._jostle_last_error()] !== 0;
  }

  /// `value` of a getter, or its error: a zero result is checked against the last error.
  got(fn, value, cppName = null) {
    if (!value) this.check(fn, !this.failed(), cppName);
    return value;
  }

  // --- Arguments --------------------------------------------------------------------------

  /// The address of a handle {index, generation, world} laid out as argument `which` (0
  /// or 1).
  handle(id, which = 0) {
    const at = this.scratch + (which === 0 ? HANDLE : OTHER), words = this.m.HEAPU32;
    words[at >> 2] = id.index;
    words[(at >> 2) + 1] = id.generation;
    words[(at >> 2) + 2] = id.serial;
    return at;
  }

  /// The address of vector argument `which` (0, 1 or 2) holding {x, y}.
  vector(x, y, which = 0) {
    const at = this.scratch + VECTORS + 8 * which, floats = this.m.HEAPF32;
    floats[at >> 2] = x;
    floats[(at >> 2) + 1] = y;
    return at;
  }

  /// The address of a jostle_query_filter from the game's {mask, category,
  /// includeSensors, ignore} (each optional: left out or undefined, its default), or 0
  /// (NULL: the default filter).
  filter(fn, filter, world) {
    if (filter === undefined || filter === null) return 0;
    if (typeof filter !== "object" || Array.isArray(filter))
      throw new TypeError(`${fn}: filter must be an object {mask, category, includeSensors, ignore}, got ${Array.isArray(filter) ? "an array" : typeof filter}`);
    const m = this.m, at = this.scratch + FILTER, L = this.layout.query_filter;
    m._jostle_default_query_filter(at);
    const words = m.HEAPU32;
    for (const key of Object.keys(filter)) {
      const value = filter[key];
      if (value === undefined) continue; // as if left out: its default, as debugDraw's options
      if (key === "mask" || key === "category") {
        words[(at + L[key]) >> 2] = args.bits(fn, `filter.${key}`, value);
      } else if (key === "includeSensors") {
        if (typeof value !== "boolean")
          throw new TypeError(`${fn}: filter.includeSensors must be true or false, got ${value}`);
        m.HEAPU8[at + L.include_sensors] = value ? 1 : 0;
      } else if (key === "ignore") {
        if (value === null) continue;
        if (!world.owns(value))
          throw new TypeError(`${fn}: filter.ignore must be a Body of this world or null`);
        const to = (at + L.ignore) >> 2;
        words[to] = value.index;
        words[to + 1] = value.generation;
        words[to + 2] = value.serial;
      } else {
        throw new TypeError(`${fn}: filter has no field "${key}" (mask, category, includeSensors, ignore)`);
      }
    }
    return at;
  }

  /// The address of a jostle_debug_draw_options from the game's options (each optional),
  /// kept for the next call. Names as in JavaScript (markLength), checked as to type here
  /// and as to range by the module.
  debugDrawOptions(fn, options) {
    options ??= {};
    args.object(fn, "options", options);
    const m = this.m, L = this.layout.debug_draw_options, P = this.layout.debug_palette;
    if (this.drawOptions === 0) this.drawOptions = m._malloc(L.size);
    const at = this.drawOptions;
    m._jostle_default_debug_draw_options(at);
    for (const key of Object.keys(options)) {
      const value = options[key], name = `options.${key}`;
      if (value === undefined) continue; // as if left out: its default
      if (["shapes", "contacts", "velocities", "touching", "grid"].includes(key)) {
        m.HEAPU8[at + L[key]] = args.boolean(fn, name, value) ? 1 : 0;
      } else if (key === "markLength") {
        m.HEAPF32[(at + L.mark_length) >> 2] = args.number(fn, name, value);
      } else if (key === "viewMin" || key === "viewMax") {
        const [x, y] = args.vector(fn, name, value), to = (at + L[snake(key)]) >> 2;
        m.HEAPF32[to] = x;
        m.HEAPF32[to + 1] = y;
      } else if (key === "palette") {
        const palette = args.object(fn, name, value), base = at + L.palette;
        for (const colour of Object.keys(palette)) {
          if (palette[colour] === undefined) continue;
          const member = P[snake(colour)], field = `${name}.${colour}`;
          if (member === undefined || colour === "size" || colour.includes("_"))
            throw new TypeError(`${fn}: ${name} has no field "${colour}"`);
          if (colour.endsWith("Percent")) {
            m.HEAP32[(base + member) >> 2] = args.integer(fn, field, palette[colour]);
          } else { // 0xRRGGBBAA as jostle_colour's bytes r, g, b, a
            const c = args.bits(fn, field, palette[colour]), bytes = m.HEAPU8, to = base + member;
            bytes[to] = c >>> 24;
            bytes[to + 1] = (c >>> 16) & 255;
            bytes[to + 2] = (c >>> 8) & 255;
            bytes[to + 3] = c & 255;
          }
        }
      } else {
        throw new TypeError(`${fn}: options has no field "${key}" (shapes, contacts, velocities, touching, grid, markLength, viewMin, viewMax, palette)`);
      }
    }
    return at;
  }

  /// Calls `call` with a pointer to `text` in the module's memory, as UTF-8; frees it after.
  withText(text, call) {
    const m = this.m, size = m.lengthBytesUTF8(text) + 1, pointer = m._malloc(size);
    try {
      m.stringToUTF8(text, pointer, size);
      return call(pointer);
    } finally {
      m._free(pointer);
    }
  }

  // --- Results ----------------------------------------------------------------------------

  text(pointer) {
    return this.m.UTF8ToString(pointer);
  }

  /// The jostle_vec2 at `at` as {x, y}.
  vec(at) {
    const floats = this.m.HEAPF32;
    return {x: floats[at >> 2], y: floats[(at >> 2) + 1]};
  }

  float(at) {
    return this.m.HEAPF32[at >> 2];
  }

  /// A buffer of at least `size` bytes in the module's memory, kept for the next call.
  bufferOf(size) {
    if (size > this.bufferSize) {
      this.m._free(this.buffer);
      this.bufferSize = Math.max(size, 2 * this.bufferSize, 1024);
      this.buffer = this.m._malloc(this.bufferSize);
    }
    return this.buffer;
  }

  /// The `count` floats at `at` as a Float32Array over the module's memory, made once for
  /// a place and kept (a view is an object: a new one each frame would be garbage). Valid
  /// until the module is next called.
  floatsAt(at, count) {
    const view = this.view;
    if (view !== undefined && view.buffer === this.m.HEAPF32.buffer && view.byteOffset === at && view.length === count)
      return view;
    return (this.view = new Float32Array(this.m.HEAPF32.buffer, at, count));
  }

  /// Calls `fill(buffer, capacity)` of a C function under the buffer rule (it writes at
  /// most `capacity` items of `size` bytes and returns how many there are), again with
  /// room for all if they did not fit; returns [address, count].
  many(fn, size, fill) {
    let capacity = Math.max(16, this.bufferSize / size | 0);
    for (;;) {
      const at = this.bufferOf(capacity * size), count = fill(at, capacity);
      if (count === 0) this.check(fn, !this.failed());
      if (count <= capacity) return [at, count];
      capacity = count;
    }
  }
}
