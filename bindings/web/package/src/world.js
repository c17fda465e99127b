// A world of a game, over jostle.h's jostle_world: its settings, bodies and tile maps,
// the step and what it did (events), reads of every body at once, snapshots.
import * as args from "./args.js";
import {Body} from "./body.js";
import {TileMap} from "./tile_map.js";
import {handleAt} from "./handle.js";
import * as queries from "./queries.js";

const SOLVERS = ["classic", "physical"];
const FRICTION_MIXES = ["min", "geometricMean"];
/// The renderer's functions beside line, by their bit in jostle_web_debug_draw's `functions`.
const DRAWN = ["box", "roundedBox", "triangle", "point"];

/// A colour's bytes r, g, b, a at `at` as 0xRRGGBBAA.
export const colourAt = (bytes, at) =>
  ((bytes[at] << 24) | (bytes[at + 1] << 16) | (bytes[at + 2] << 8) | bytes[at + 3]) >>> 0;

/// Makes `count` calls of a DebugDrawList at `at` (jostle::DebugDrawList::Command, nine
/// 32-bit words each: six floats, the fill's and the outline's bytes, the kind) on `draw`.
export function drawCalls(m, at, count, draw) {
  for (let i = 0; i < count; ++i) {
    // The views are taken afresh for each call: the game's function may grow the memory.
    const p = (at >> 2) + 9 * i, f = m.HEAPF32, bytes = m.HEAPU8;
    const fill = colourAt(bytes, 4 * (p + 6)), outline = colourAt(bytes, 4 * (p + 7));
    switch (m.HEAPU32[p + 8]) {
      case 0: draw.line(f[p], f[p + 1], f[p + 2], f[p + 3], fill); break;
      case 1: draw.box(f[p], f[p + 1], f[p + 2], f[p + 3], fill, outline); break;
      case 2: draw.roundedBox(f[p], f[p + 1], f[p + 2], f[p + 3], f[p + 4], fill, outline); break;
      case 3: draw.triangle(f[p], f[p + 1], f[p + 2], f[p + 3], f[p + 4], f[p + 5], fill, outline); break;
      default: draw.point(f[p], f[p + 1], f[p + 2], fill);
    }
  }
}

export class World {
  constructor(jostle, pointer) {
    this.jostle = jostle;
    this.rt = jostle.rt;
    this.pointer = pointer; // the jostle_world*; null once destroyed
    // The Body of each storage slot, so that a body is one object wherever it is met
    // (createBody, events, queries); replaced when the slot's body is a newer one.
    this.bodyOfSlot = [];
    this.tileMapOfSlot = [];
    this.preSolve = null;
    jostle.worlds.set(pointer, this);
  }

  /// The world's jostle_world*, or an Error if it was destroyed.
  live(fn) {
    if (this.pointer === null) throw new Error(`${fn}: the world was destroyed`);
    return this.pointer;
  }

  /// True if `body` is a Body of this world (live or not).
  owns(body) {
    return body instanceof Body && body.world === this;
  }

  /// The Body of the handle at `at` in the module's memory (null for the null handle).
  bodyAt(at) {
    return handleAt(this, at, this.bodyOfSlot, Body);
  }

  // --- Settings ---------------------------------------------------------------------------

  get gravity() {
    const rt = this.rt;
    rt.m._jostle_world_get_gravity(rt.out, this.live("gravity"));
    return rt.vec(rt.out);
  }
  set gravity(value) {
    const [x, y] = args.vector("gravity", "gravity", value);
    this.rt.check("gravity", this.rt.m._jostle_world_set_gravity(this.live("gravity"), this.rt.vector(x, y)));
  }

  /// The largest speed of a dynamic body; Infinity: no clamp.
  get maxVelocity() { return this.rt.got("maxVelocity", this.rt.m._jostle_world_get_max_velocity(this.live("maxVelocity"))); }
  set maxVelocity(value) {
    if (value !== Infinity) args.number("maxVelocity", "maxVelocity", value);
    this.rt.check("maxVelocity", this.rt.m._jostle_world_set_max_velocity(this.live("maxVelocity"), value));
  }

  /// "physical" (the default) or "classic" (the tutorial's model).
  get solver() { return SOLVERS[this.rt.m._jostle_world_get_solver(this.live("solver"))]; }
  set solver(value) {
    const solver = SOLVERS.indexOf(value);
    if (solver < 0) throw new TypeError(`solver: must be "classic" or "physical", got ${args.describe(value)}`);
    this.rt.check("solver", this.rt.m._jostle_world_set_solver(this.live("solver"), solver));
  }

  /// Bodies at rest fall asleep (physical model; on by default).
  get sleeping() { return this.rt.m._jostle_world_get_sleeping(this.live("sleeping")) !== 0; }
  set sleeping(value) {
    args.boolean("sleeping", "sleeping", value);
    this.rt.check("sleeping", this.rt.m._jostle_world_set_sleeping(this.live("sleeping"), value));
  }

  /// Threads the world steps on: 1 in WebAssembly, which is built without threads.
  get workers() { return this.rt.m._jostle_world_get_workers(this.live("workers")); }

  /// The classic model's switches: {mass, coulomb, ccd}.
  get classicOptions() {
    const rt = this.rt, L = rt.layout.classic_options, bytes = rt.m.HEAPU8;
    rt.m._jostle_world_get_classic_options(rt.out, this.live("classicOptions"));
    return {mass: bytes[rt.out + L.mass] !== 0, coulomb: bytes[rt.out + L.coulomb] !== 0,
            ccd: bytes[rt.out + L.ccd] !== 0};
  }
  set classicOptions(value) {
    const fn = "classicOptions", rt = this.rt, L = rt.layout.classic_options;
    const options = {...this.classicOptions, ...args.object(fn, fn, value)};
    const at = rt.out + 64;
    for (const key of Object.keys(options)) {
      if (!(key in L) || key === "size") throw new TypeError(`${fn}: no option "${key}" (mass, coulomb, ccd)`);
      rt.m.HEAPU8[at + L[key]] = args.boolean(fn, `${fn}.${key}`, options[key]) ? 1 : 0;
    }
    rt.check(fn, rt.m._jostle_world_set_classic_options(this.live(fn), at));
  }

  /// The physical model's settings: {velocityIterations, positionIterations, slop,
  /// correction, restitutionThreshold, frictionMix ("min" or "geometricMean"),
  /// maxContactsPerBody}, as a scene file's "physical" has them.
  get physicalOptions() {
    const rt = this.rt, L = rt.layout.physical_options, at = rt.out;
    rt.m._jostle_world_get_physical_options(at, this.live("physicalOptions"));
    const ints = rt.m.HEAP32, floats = rt.m.HEAPF32;
    return {velocityIterations: ints[(at + L.velocity_iterations) >> 2],
            positionIterations: ints[(at + L.position_iterations) >> 2],
            slop: floats[(at + L.slop) >> 2], correction: floats[(at + L.correction) >> 2],
            restitutionThreshold: floats[(at + L.restitution_threshold) >> 2],
            frictionMix: FRICTION_MIXES[ints[(at + L.friction_mix) >> 2]],
            maxContactsPerBody: ints[(at + L.max_contacts_per_body) >> 2]};
  }
  set physicalOptions(value) {
    const fn = "physicalOptions", rt = this.rt, L = rt.layout.physical_options;
    const options = {...this.physicalOptions, ...args.object(fn, fn, value)};
    const at = rt.out, ints = rt.m.HEAP32, floats = rt.m.HEAPF32;
    const integers = {velocityIterations: "velocity_iterations", positionIterations: "position_iterations",
                      maxContactsPerBody: "max_contacts_per_body"};
    const reals = {slop: "slop", correction: "correction", restitutionThreshold: "restitution_threshold"};
    for (const key of Object.keys(options)) {
      if (key in integers) ints[(at + L[integers[key]]) >> 2] = args.integer(fn, `${fn}.${key}`, options[key]);
      else if (key in reals) floats[(at + L[reals[key]]) >> 2] = args.number(fn, `${fn}.${key}`, options[key]);
      else if (key === "frictionMix") {
        const mix = FRICTION_MIXES.indexOf(options[key]);
        if (mix < 0) throw new TypeError(`${fn}: ${fn}.frictionMix must be "min" or "geometricMean", got ${args.describe(options[key])}`);
        ints[(at + L.friction_mix) >> 2] = mix;
      } else throw new TypeError(`${fn}: no option "${key}"`);
    }
    rt.check(fn, rt.m._jostle_world_set_physical_options(this.live(fn), at));
  }

  // --- Bodies and tile maps -----------------------------------------------------------------

  /// A body from a scene file's body object: {type, x, y, hw, hh, vx, vy, bounce, ...}
  /// (docs/scene-format.md), checked as the scene loader checks a file's; userData is
  /// any JavaScript value, kept on the Body.
  createBody(def) {
    const fn = "createBody";
    args.object(fn, "def", def);
    const {userData, ...fields} = def;
    const text = args.json(fn, fields);
    const world = this.live(fn), rt = this.rt, m = rt.m;
    const read = rt.withText(text, (p) => m._jostle_web_read_body(world, p));
    rt.check(fn, read !== 0);
    m._jostle_body_create(rt.out, world, read);
    rt.check(fn, m.HEAPU32[(rt.out >> 2) + 1] !== 0);
    // The object may be one the game met before: the same handle made again after a
    // restore (docs/rollback.md). Its userData is this def's.
    const body = this.bodyAt(rt.out);
    body.userData = userData;
    return body;
  }

  /// A tile map from a scene file's tile map object: {x, y, tile, rows: ["#..#", ...],
  /// friction, bounce, category, mask, oneWay, sensor} (docs/tilemaps.md); userData is any
  /// JavaScript value, kept on the TileMap (a body's: body.tileMap.userData).
  createTileMap(def) {
    const fn = "createTileMap";
    const {userData, ...fields} = args.object(fn, "def", def);
    const text = args.json(fn, {bodies: [], tilemaps: [fields]});
    const world = this.live(fn), rt = this.rt, m = rt.m;
    try {
      const read = rt.withText(text, (p) => m._jostle_web_read_scene(p));
      rt.check(fn, read !== 0);
      m._jostle_tile_map_create(rt.out, world, m._jostle_web_scene_tile_map(0));
      rt.check(fn, m.HEAPU32[(rt.out >> 2) + 1] !== 0);
      const map = this.tileMapAt(rt.out);
      map.userData = userData;
      return map;
    } catch (error) {
      // The loader names the map as a scene's first: the game gave one map alone.
      error.message = error.message.replace(/^createTileMap: tilemaps\[0\]\.?:? ?/, `${fn}: `);
      throw error;
    } finally {
      m._jostle_web_forget_scene();
    }
  }

  /// This world's Body (or TileMap) of the same slot and generation as `other`, a Body or
  /// TileMap of another world whose snapshot this one restored (a saved game, a peer's
  /// state); null if none is alive here.
  adopt(other) {
    const fn = "adopt", world = this.live(fn), rt = this.rt;
    if (other instanceof Body) {
      rt.m._jostle_world_adopt_body(rt.out, world, rt.handle(other));
      return this.bodyAt(rt.out);
    }
    if (other instanceof TileMap) {
      rt.m._jostle_world_adopt_tile_map(rt.out, world, rt.handle(other));
      return this.tileMapAt(rt.out);
    }
    throw new TypeError(`${fn}: other must be a Body or a TileMap, got ${args.describe(other)}`);
  }

  /// The TileMap of the handle at `at` (null for the null handle), as bodyAt.
  tileMapAt(at) {
    return handleAt(this, at, this.tileMapOfSlot, TileMap);
  }

  /// How many bodies there are, tile maps' included.
  get bodyCount() { return this.rt.m._jostle_world_body_count(this.live("bodyCount")); }

  /// Every body, tile maps' included, in creation order: the order of readPositions.
  bodies() {
    const world = this.live("bodies"), rt = this.rt, size = rt.layout.body_id.size;
    const [at, count] = rt.many("bodies", size, (out, capacity) => rt.m._jostle_world_bodies(world, out, capacity));
    const bodies = new Array(count);
    for (let i = 0; i < count; i++) bodies[i] = this.bodyAt(at + i * size);
    return bodies;
  }

  /// Every body's centre, x then y, in the order of bodies(), into `out` (a Float32Array
  /// of at least 2 * bodyCount numbers: what does not fit is left out); returns how many
  /// bodies there are. One call for all, and no garbage: keep `out` from frame to frame.
  readPositions(out) { return this.readVectors("readPositions", "_jostle_world_read_positions", out); }
  /// Every body's velocity, as readPositions.
  readVelocities(out) { return this.readVectors("readVelocities", "_jostle_world_read_velocities", out); }
  /// Every body's half extents, as readPositions.
  readHalfExtents(out) { return this.readVectors("readHalfExtents", "_jostle_world_read_half_extents", out); }

  /// Every body's shape, for drawing, six numbers a body in the order of bodies() into
  /// `out` (a Float32Array; what does not fit is left out): half width, half height,
  /// radius, slope x, slope y (docs/slopes-and-shapes.md), flags (type 0 static, 1
  /// kinematic, 2 dynamic; + 4 sensor, + 8 segment, + 16 awake). Returns how many bodies
  /// there are. A shape is fixed when its body is made: read them when bodies come and go.
  readShapes(out) {
    const fn = "readShapes";
    args.floats(fn, "out", out);
    const world = this.live(fn), rt = this.rt, capacity = (out.length / 6) | 0;
    const at = rt.bufferOf(24 * Math.max(capacity, 1));
    const count = rt.m._jostle_web_read_shapes(world, at, capacity);
    out.set(rt.floatsAt(at, 6 * Math.min(count, capacity)));
    return count;
  }

  /// Draws the world as the engine sees it through `draw`, the game's renderer: an object
  /// whose line(x1, y1, x2, y2, colour) is required and whose box(x, y, hw, hh, fill,
  /// outline), roundedBox(x, y, hw, hh, radius, fill, outline), triangle(x1, y1, x2, y2,
  /// x3, y3, fill, outline) and point(x, y, size, colour) are drawn with lines when it has
  /// none. World units; colours 0xRRGGBBAA (a fill of opacity 0 is not filled). `options`:
  /// {shapes, contacts, velocities, touching, grid, markLength, viewMin, viewMax, palette}
  /// (docs/debug-draw.md).
  debugDraw(draw, options) {
    const fn = "debugDraw";
    args.object(fn, "draw", draw);
    args.func(fn, "draw.line", draw.line);
    let functions = 0;
    DRAWN.forEach((name, i) => {
      if (draw[name] === undefined) return;
      args.func(fn, `draw.${name}`, draw[name]);
      functions |= 1 << i;
    });
    const world = this.live(fn), rt = this.rt, m = rt.m;
    // The module keeps one list of calls: a function of the game's may not draw again.
    if (rt.drawing) throw new Error(`${fn}: called from a function of debugDraw`);
    const at = m._jostle_web_debug_draw(world, rt.debugDrawOptions(fn, options), functions, rt.out);
    rt.check(fn, at !== 0);
    rt.drawing = true;
    try {
      drawCalls(m, at, m.HEAP32[rt.out >> 2], draw);
    } finally {
      rt.drawing = false;
    }
  }

  readVectors(fn, name, out) {
    args.floats(fn, "out", out);
    const world = this.live(fn), rt = this.rt, m = rt.m;
    const capacity = out.length >> 1, at = rt.bufferOf(8 * Math.max(capacity, 1));
    const count = m[name](world, at, capacity);
    out.set(rt.floatsAt(at, 2 * Math.min(count, capacity)));
    return count;
  }

  // --- The step and what it did -------------------------------------------------------------

  /// Advances the world by dt seconds (> 0): 1 / 60 for a 60 Hz game.
  step(dt) {
    const fn = "step";
    args.number(fn, "dt", dt);
    const ok = this.rt.m._jostle_world_step(this.live(fn), dt);
    this.jostle.rethrow();
    this.rt.check(fn, ok);
  }

  /// Pairs that started touching in the last step: [{a, b, normal: {x, y},
  /// approachSpeed, point: {x, y}}], a created first, the normal from b towards a.
  contactBegins() { return this.events("contactBegins", "_jostle_world_contact_begins", "contact_event", contactEvent); }
  /// Pairs that stopped touching (or one of which was destroyed) in the last step.
  contactEnds() { return this.events("contactEnds", "_jostle_world_contact_ends", "contact_event", contactEvent); }
  /// Bodies that started overlapping a sensor: [{sensor, visitor}].
  sensorBegins() { return this.events("sensorBegins", "_jostle_world_sensor_begins", "sensor_event", sensorEvent); }
  sensorEnds() { return this.events("sensorEnds", "_jostle_world_sensor_ends", "sensor_event", sensorEvent); }
  /// Bodies squeezed by a kinematic body: [{body, by, against}].
  crushBegins() { return this.events("crushBegins", "_jostle_world_crush_begins", "crush_event", crushEvent); }
  crushEnds() { return this.events("crushEnds", "_jostle_world_crush_ends", "crush_event", crushEvent); }

  events(fn, name, struct, read) {
    const rt = this.rt, m = rt.m, countAt = rt.out;
    const at = m[name](this.live(fn), countAt);
    const count = m.HEAP32[countAt >> 2], L = rt.layout[struct], list = new Array(count);
    for (let i = 0; i < count; i++) list[i] = read(this, at + i * L.size, L);
    return list;
  }

  /// Pairs the last step left out because a body had more than maxContactsPerBody.
  get pairsLeftOut() { return this.rt.m._jostle_world_pairs_left_out(this.live("pairsLeftOut")); }

  /// Where the last step's time went, in milliseconds: {step, riders, ..., sleep}.
  profile() {
    const rt = this.rt, at = rt.bufferOf(4 * rt.layout.profile.length);
    rt.m._jostle_world_get_profile(at, this.live("profile"));
    const profile = {}, floats = rt.m.HEAPF32;
    rt.layout.profile.forEach((stage, i) => { profile[stage] = floats[(at >> 2) + i]; });
    return profile;
  }

  /// Calls `callback(collision)` for every pair the solver is about to respond to, with
  /// {a, b, normal, depth, bounce, friction}; it returns false to let the pair pass
  /// through this time, and may change bounce and friction for this pair and step. null
  /// removes it.
  setPreSolve(callback) {
    const fn = "setPreSolve";
    if (callback !== null) args.func(fn, "callback", callback);
    this.rt.check(fn, this.rt.m._jostle_web_set_pre_solve(this.live(fn), callback !== null));
    this.preSolve = callback;
  }

  // --- Queries (queries.js) -----------------------------------------------------------------

  /// The bodies that contain `point`, in creation order.
  queryPoint(point, filter) { return queries.point(this, point, filter); }
  /// The bodies that share area with the box of `centre` and `half` extents.
  queryBox(centre, half, filter) { return queries.box(this, centre, half, filter); }
  /// queryBox by corners.
  queryRect(min, max, filter) { return queries.rect(this, min, max, filter); }
  /// The first body on the segment: {body, point, normal, fraction}, or null.
  rayCast(from, to, filter) { return queries.rayCast(this, from, to, filter); }
  /// Every body on the segment, nearest first.
  rayCastAll(from, to, filter) { return queries.rayCastAll(this, from, to, filter); }
  /// Where a box swept by `translation` first touches a body: {body, centre, normal,
  /// fraction}, or null.
  boxCast(centre, half, translation, filter) { return queries.boxCast(this, centre, half, 0, translation, filter); }
  roundedBoxCast(centre, half, radius, translation, filter) {
    return queries.boxCast(this, centre, half, radius, translation, filter, "roundedBoxCast");
  }
  circleCast(centre, radius, translation, filter) { return queries.circleCast(this, centre, radius, translation, filter); }
  /// Moves a box as bump.lua does, sliding along what it meets; nothing in the world
  /// moves: {centre, hits: [{body, normal}]}.
  moveAndSlide(centre, half, translation, filter) {
    return queries.moveAndSlide(this, centre, half, 0, translation, filter, "moveAndSlide");
  }
  roundedMoveAndSlide(centre, half, radius, translation, filter) {
    return queries.moveAndSlide(this, centre, half, radius, translation, filter, "roundedMoveAndSlide");
  }

  // --- Snapshots (docs/snapshots.md) ----------------------------------------------------------

  /// How many bytes snapshot() writes now.
  snapshotSize() {
    const fn = "snapshotSize", size = this.rt.m._jostle_world_snapshot_size(this.live(fn));
    this.rt.check(fn, size !== 0);
    return size;
  }

  /// Everything that decides the world's future, as the bytes C and C++ write: a new array,
  /// or the front of `into` (a Uint8Array long enough: a rollback loop's own, no new buffer).
  snapshot(into) {
    const fn = "snapshot", world = this.live(fn), rt = this.rt, m = rt.m;
    if (into !== undefined && !(into instanceof Uint8Array))
      throw new TypeError(`${fn}: into must be a Uint8Array, got ${args.describe(into)}`);
    // Written into the buffer as it is, in one pass; the size is asked for only when it
    // is too small (the first snapshot, a world that grew).
    let at = rt.bufferOf(1), size = m._jostle_world_snapshot(world, at, rt.bufferSize);
    if (size === 0) {
      const needed = m._jostle_world_snapshot_size(world);
      rt.check(fn, needed !== 0);
      at = rt.bufferOf(needed);
      size = m._jostle_world_snapshot(world, at, needed);
      rt.check(fn, size === needed);
    }
    if (into === undefined || into.length < size)
      return m.HEAPU8.slice(at, at + size);
    into.set(m.HEAPU8.subarray(at, at + size));
    return into.subarray(0, size);
  }

  /// Makes the world what it was when `bytes` were taken; Body objects of that time name
  /// their bodies again, those made since are stale.
  restore(bytes) {
    const fn = "restore";
    if (!(bytes instanceof Uint8Array))
      throw new TypeError(`${fn}: snapshot must be a Uint8Array (from snapshot()), got ${args.describe(bytes)}`);
    const world = this.live(fn), rt = this.rt, at = rt.bufferOf(bytes.length);
    rt.m.HEAPU8.set(bytes, at);
    rt.check(fn, rt.m._jostle_world_restore(world, at, bytes.length));
    this.forgetReplacedHandles();
  }

  /// After a restore, forgets the object of each slot that now holds a body (or a map) of
  /// another generation than the object's (its slot was reused after the snapshot), so that
  /// the body the restore brought back is one object again; the userData rule of
  /// docs/snapshots.md follows.
  forgetReplacedHandles() {
    const world = this.pointer, rt = this.rt, size = rt.layout.body_id.size;
    const [at, count] = rt.many("restore", size, (out, capacity) => rt.m._jostle_world_bodies(world, out, capacity));
    const words = rt.m.HEAPU32;
    for (let i = 0; i < count; i++) {
      const p = (at + i * size) >> 2, known = this.bodyOfSlot[words[p]];
      if (known !== undefined && known.generation !== words[p + 1]) delete this.bodyOfSlot[words[p]];
    }
    this.tileMapOfSlot.forEach((map, slot) => {
      if (!map.valid) delete this.tileMapOfSlot[slot];
    });
  }

  /// A hash of exactly what a snapshot holds, as 16 hexadecimal digits.
  stateHash() {
    const fn = "stateHash", hash = this.rt.text(this.rt.m._jostle_web_state_hash(this.live(fn)));
    this.rt.check(fn, hash !== "");
    return hash;
  }

  /// Frees the world; it and its bodies may not be used after.
  destroy() {
    const fn = "destroy", pointer = this.live(fn);
    this.rt.check(fn, this.rt.m._jostle_world_destroy(pointer));
    this.jostle.worlds.delete(pointer);
    this.pointer = null;
  }
}

function contactEvent(world, at, L) {
  const rt = world.rt;
  return {a: world.bodyAt(at + L.a), b: world.bodyAt(at + L.b), normal: rt.vec(at + L.normal),
          approachSpeed: rt.float(at + L.approach_speed), point: rt.vec(at + L.point)};
}

function sensorEvent(world, at, L) {
  return {sensor: world.bodyAt(at + L.sensor), visitor: world.bodyAt(at + L.visitor)};
}

function crushEvent(world, at, L) {
  return {body: world.bodyAt(at + L.body), by: world.bodyAt(at + L.by), against: world.bodyAt(at + L.against)};
}
