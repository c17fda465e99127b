// A body of a world: a handle ({index, generation} of jostle.h's jostle_body_id) that the
// module checks at every call, so that a body destroyed since is refused as it is in C
// and Lua. Its settings are properties (body.friction = 0.2), read and written through
// jostle.h's getters and setters.
import * as args from "./args.js";
import {Handle} from "./handle.js";

const TYPES = ["static", "kinematic", "dynamic"];
const RESPONSES = ["slide", "touch", "cross", "bounce", "ignore"];

export class Body extends Handle {
  constructor(world, index, generation, serial) {
    super(world, index, generation, serial);
    /// Yours: any value, kept on this object (createBody's def.userData).
    this.userData = undefined;
  }

  /// Calls a getter of a struct result written at the scratch's out; returns its address.
  callOut(fn, name) {
    const rt = this.world.rt;
    rt.m[name](rt.out, this.world.live(fn), rt.handle(this));
    return rt.out;
  }

  /// A vector getter's {x, y}; {0, 0} is checked against the last error.
  getVector(fn, name) {
    const rt = this.world.rt, v = rt.vec(this.callOut(fn, name));
    if (v.x === 0 && v.y === 0) rt.check(fn, !rt.failed());
    return v;
  }

  setVector(fn, name, x, y, names = ["x", "y"]) {
    args.number(fn, names[0], x);
    args.number(fn, names[1], y);
    this.world.rt.check(fn, this.call(fn, name, this.world.rt.vector(x, y)));
  }

  /// True while the body exists: not destroyed, its world not destroyed.
  get valid() {
    const w = this.world;
    return w.pointer !== null && w.rt.m._jostle_body_is_valid(w.pointer, w.rt.handle(this)) !== 0;
  }

  /// Removes the body from its world; this object is stale after.
  destroy() { this.world.rt.check("destroy", this.call("destroy", "_jostle_body_destroy"), "destroyBody"); }

  /// "static", "kinematic" or "dynamic".
  get type() {
    const type = this.call("type", "_jostle_body_get_type");
    if (type === 0) this.world.rt.check("type", !this.world.rt.failed()); // static, or misuse
    return TYPES[type];
  }
  set type(value) {
    const type = TYPES.indexOf(value);
    if (type < 0) throw new TypeError(`type: must be "static", "kinematic" or "dynamic", got ${args.describe(value)}`);
    this.world.rt.check("type", this.call("type", "_jostle_body_set_type", type));
  }

  setPosition(x, y) { this.setVector("setPosition", "_jostle_body_set_position", x, y); }
  setVelocity(vx, vy) { this.setVector("setVelocity", "_jostle_body_set_velocity", vx, vy, ["vx", "vy"]); }
  setHalfExtents(hw, hh) { this.setVector("setHalfExtents", "_jostle_body_set_half_extents", hw, hh, ["hw", "hh"]); }
  /// Sets the mass from a density (mass = density * 4 * hw * hh).
  setDensity(density) {
    args.number("setDensity", "density", density);
    this.world.rt.check("setDensity", this.call("setDensity", "_jostle_body_set_density", density));
  }

  /// Adds a force (mass * units / s²) for the next step.
  applyForce(fx, fy) { this.setVector("applyForce", "_jostle_body_apply_force", fx, fy, ["fx", "fy"]); }
  /// Changes the velocity by impulse / mass at once.
  applyImpulse(ix, iy) { this.setVector("applyImpulse", "_jostle_body_apply_impulse", ix, iy, ["ix", "iy"]); }
  /// Wakes the body (and what it touches) if it sleeps.
  wake() { this.world.rt.check("wake", this.call("wake", "_jostle_body_wake")); }
  /// Falls through one-way platforms for `seconds`.
  dropThrough(seconds) {
    args.number("dropThrough", "seconds", seconds);
    this.world.rt.check("dropThrough", this.call("dropThrough", "_jostle_body_drop_through", seconds));
  }

  /// The sides it touched at the end of the last step: {floor, ceiling, wallLeft, wallRight}.
  get touching() {
    const rt = this.world.rt, at = this.callOut("touching", "_jostle_body_get_touching");
    const L = rt.layout.touching, bytes = rt.m.HEAPU8;
    const touching = {floor: bytes[at + L.floor] !== 0, ceiling: bytes[at + L.ceiling] !== 0,
                      wallLeft: bytes[at + L.wall_left] !== 0, wallRight: bytes[at + L.wall_right] !== 0};
    if (!touching.floor && !touching.ceiling && !touching.wallLeft && !touching.wallRight)
      rt.check("touching", !rt.failed());
    return touching;
  }

  /// What a character stands on: {body, normal, velocity}, or null in the air.
  get ground() {
    const rt = this.world.rt, at = rt.out, L = rt.layout.ground;
    if (!this.call("ground", "_jostle_body_get_ground", at)) {
      rt.check("ground", !rt.failed());
      return null;
    }
    return {body: this.world.bodyAt(at + L.body), normal: rt.vec(at + L.normal), velocity: rt.vec(at + L.velocity)};
  }

  /// The bodies it touched at the end of the last step: [{other, normal, point, impulse}].
  contacts() {
    const fn = "contacts", rt = this.world.rt, L = rt.layout.contact_info, world = this.world;
    const [at, count] = rt.many(fn, L.size, (out, capacity) => this.call(fn, "_jostle_body_contacts", out, capacity));
    const list = new Array(count);
    for (let i = 0, p = at; i < count; i++, p += L.size)
      list[i] = {other: world.bodyAt(p + L.other), normal: rt.vec(p + L.normal), point: rt.vec(p + L.point),
                 impulse: rt.float(p + L.impulse)};
    return list;
  }

  /// True if the two touched at the end of the last step.
  isTouching(other) {
    const fn = "isTouching", rt = this.world.rt;
    if (!this.world.owns(other)) throw new TypeError(`${fn}: other must be a Body of this world, got ${args.describe(other)}`);
    return rt.got(fn, rt.m._jostle_body_is_touching(this.world.live(fn), rt.handle(this), rt.handle(other, 1))) !== 0;
  }

  /// Moves the body by (dx, dy) as bump.lua's world:move does. `filter(other)` (optional)
  /// answers each body in the way: "slide", "touch", "cross", "bounce" or "ignore".
  /// Returns {x, y, collisions: [{other, response, normal, touch, time, otherCentre,
  /// otherHalf}]}.
  move(dx, dy, filter) {
    const fn = "move", world = this.world, rt = world.rt, m = rt.m;
    args.number(fn, "dx", dx);
    args.number(fn, "dy", dy);
    if (filter !== undefined && filter !== null) args.func(fn, "filter", filter);
    const pointer = world.live(fn), result = rt.out, id = rt.handle(this), delta = rt.vector(dx, dy);
    world.jostle.moveFilter = filter ?? null;
    const ok = m._jostle_web_body_move(pointer, id, delta, filter ? 1 : 0, result);
    world.jostle.moveFilter = null;
    world.jostle.rethrow();
    rt.check(fn, ok);
    const R = rt.layout.move_result, C = rt.layout.move_collision, words = m.HEAPU32;
    const centre = rt.vec(result + R.centre), count = m.HEAP32[(result + R.count) >> 2];
    const collisions = new Array(count);
    for (let i = 0, p = words[(result + R.collisions) >> 2]; i < count; i++, p += C.size)
      collisions[i] = {other: world.bodyAt(p + C.other), response: RESPONSES[m.HEAP32[(p + C.response) >> 2]],
                       normal: rt.vec(p + C.normal), touch: rt.vec(p + C.touch), time: rt.float(p + C.time),
                       otherCentre: rt.vec(p + C.other_centre), otherHalf: rt.vec(p + C.other_half)};
    return {x: centre.x, y: centre.y, collisions};
  }

  /// The body's definition as a scene file's body object, every setting as it is now,
  /// ready to change and give to createBody.
  def() {
    const fn = "def", rt = this.world.rt;
    const text = rt.m._jostle_web_body_def(this.world.live(fn), rt.handle(this));
    rt.check(fn, text !== 0);
    const def = JSON.parse(rt.text(text));
    if (this.userData !== undefined) def.userData = this.userData;
    return def;
  }

  /// The tile map the body is part of, or null.
  get tileMap() {
    const rt = this.world.rt;
    rt.m._jostle_tile_map_of(rt.out, this.world.live("tileMap"), rt.handle(this));
    if (rt.m.HEAPU32[(rt.out >> 2) + 1] === 0) {
      rt.check("tileMap", !rt.failed(), "tileMapOf");
      return null;
    }
    return this.world.tileMapAt(rt.out);
  }
}

// The settings read and written as properties, each through jostle.h's getter and
// setter of its C name: [property, C name, kind]. A vector is {x, y} when read and
// {x, y} or [x, y] when set; bits are whole numbers in [0, 2^32).
const PROPERTIES = [
  ["position", "position", "vector"], ["velocity", "velocity", "vector"],
  ["halfExtents", "half_extents", "vector"], ["bounce", "bounce", "number"],
  ["friction", "friction", "number"], ["mass", "mass", "number"],
  ["gravityScale", "gravity_scale", "number"], ["damping", "damping", "number"],
  ["bullet", "bullet", "boolean"], ["oneWay", "one_way", "vector"],
  ["category", "category", "bits"], ["mask", "mask", "bits"], ["sensor", "sensor", "boolean"],
  ["character", "character", "boolean"], ["wallFriction", "wall_friction", "number"],
  ["floorAngle", "floor_angle", "number"], ["surfaceVelocity", "surface_velocity", "vector"],
  ["cornerCorrection", "corner_correction", "number"], ["stepUp", "step_up", "number"],
  ["snapDown", "snap_down", "number"], ["walkSpeed", "walk_speed", "number"],
];
// Read only: [property, C name, kind].
const READ_ONLY = [["awake", "awake", "boolean"], ["separation", "separation", "vector"]];

function getterOf(property, c, kind) {
  const name = kind === "boolean" ? `_jostle_body_is_${c}` : `_jostle_body_get_${c}`;
  switch (kind) {
    case "vector": return function () { return this.getVector(property, name); };
    case "boolean": return function () { return this.world.rt.got(property, this.call(property, name)) !== 0; };
    case "bits": return function () { return this.world.rt.got(property, this.call(property, name)) >>> 0; };
    default: return function () { return this.world.rt.got(property, this.call(property, name)); };
  }
}

function setterOf(property, c, kind) {
  const name = `_jostle_body_set_${c}`;
  const check = {number: args.number, boolean: args.boolean, bits: args.bits}[kind];
  if (kind === "vector")
    return function (value) {
      const [x, y] = args.vector(property, property, value);
      this.setVector(property, name, x, y);
    };
  return function (value) {
    check(property, property, value);
    this.world.rt.check(property, this.call(property, name, kind === "boolean" ? (value ? 1 : 0) : value));
  };
}

for (const [property, c, kind] of PROPERTIES)
  Object.defineProperty(Body.prototype, property,
                        {get: getterOf(property, c, kind), set: setterOf(property, c, kind), configurable: true});
for (const [property, c, kind] of READ_ONLY)
  Object.defineProperty(Body.prototype, property, {get: getterOf(property, c, kind), configurable: true});
