// The queries of a world (docs/queries.md): they look at every body where it is now and
// change nothing. Vectors are {x, y} or [x, y]; a filter is {mask, category,
// includeSensors, ignore}, each optional.
import * as args from "./args.js";

/// The bodies a query of the buffer rule found: fill(filter, out, capacity) → count.
function found(world, fn, filter, fill) {
  const rt = world.rt, size = rt.layout.body_id.size;
  const [at, count] = rt.many(fn, size, (out, capacity) => fill(rt.filter(fn, filter, world), out, capacity));
  const bodies = new Array(count);
  for (let i = 0; i < count; i++) bodies[i] = world.bodyAt(at + i * size);
  return bodies;
}

export function point(world, point, filter) {
  const fn = "queryPoint", [x, y] = args.vector(fn, "point", point), p = world.live(fn), rt = world.rt;
  return found(world, fn, filter, (f, out, capacity) =>
    rt.m._jostle_query_point(p, rt.vector(x, y), f, out, capacity));
}

export function box(world, centre, half, filter) {
  const fn = "queryBox", p = world.live(fn), rt = world.rt;
  const [cx, cy] = args.vector(fn, "centre", centre), [hw, hh] = args.vector(fn, "half", half);
  return found(world, fn, filter, (f, out, capacity) =>
    rt.m._jostle_query_box(p, rt.vector(cx, cy), rt.vector(hw, hh, 1), f, out, capacity));
}

export function rect(world, min, max, filter) {
  const fn = "queryRect", p = world.live(fn), rt = world.rt;
  const [x0, y0] = args.vector(fn, "min", min), [x1, y1] = args.vector(fn, "max", max);
  return found(world, fn, filter, (f, out, capacity) =>
    rt.m._jostle_query_rect(p, rt.vector(x0, y0), rt.vector(x1, y1, 1), f, out, capacity));
}

function rayHit(world, at) {
  const rt = world.rt, L = rt.layout.ray_hit;
  return {body: world.bodyAt(at + L.body), point: rt.vec(at + L.point), normal: rt.vec(at + L.normal),
          fraction: rt.float(at + L.fraction)};
}

export function rayCast(world, from, to, filter) {
  const fn = "rayCast", p = world.live(fn), rt = world.rt;
  const [x0, y0] = args.vector(fn, "from", from), [x1, y1] = args.vector(fn, "to", to);
  const f = rt.filter(fn, filter, world);
  if (!rt.m._jostle_ray_cast(p, rt.vector(x0, y0), rt.vector(x1, y1, 1), f, rt.out)) {
    rt.check(fn, !rt.failed());
    return null;
  }
  return rayHit(world, rt.out);
}

export function rayCastAll(world, from, to, filter) {
  const fn = "rayCastAll", p = world.live(fn), rt = world.rt, size = rt.layout.ray_hit.size;
  const [x0, y0] = args.vector(fn, "from", from), [x1, y1] = args.vector(fn, "to", to);
  const [at, count] = rt.many(fn, size, (out, capacity) =>
    rt.m._jostle_ray_cast_all(p, rt.vector(x0, y0), rt.vector(x1, y1, 1), rt.filter(fn, filter, world), out, capacity));
  const hits = new Array(count);
  for (let i = 0; i < count; i++) hits[i] = rayHit(world, at + i * size);
  return hits;
}

function castHit(world, at) {
  const rt = world.rt, L = rt.layout.box_cast_hit;
  return {body: world.bodyAt(at + L.body), centre: rt.vec(at + L.centre), normal: rt.vec(at + L.normal),
          fraction: rt.float(at + L.fraction)};
}

/// boxCast, or roundedBoxCast when fn says so (radius then checked).
export function boxCast(world, centre, half, radius, translation, filter, fn = "boxCast") {
  const p = world.live(fn), rt = world.rt;
  const [cx, cy] = args.vector(fn, "centre", centre), [hw, hh] = args.vector(fn, "half", half);
  const [tx, ty] = args.vector(fn, "translation", translation);
  const f = rt.filter(fn, filter, world), m = rt.m;
  const c = rt.vector(cx, cy), h = rt.vector(hw, hh, 1), t = rt.vector(tx, ty, 2);
  const hit = fn === "boxCast" ? m._jostle_box_cast(p, c, h, t, f, rt.out)
                               : m._jostle_rounded_box_cast(p, c, h, args.number(fn, "radius", radius), t, f, rt.out);
  if (!hit) {
    rt.check(fn, !rt.failed());
    return null;
  }
  return castHit(world, rt.out);
}

export function circleCast(world, centre, radius, translation, filter) {
  const fn = "circleCast", p = world.live(fn), rt = world.rt;
  const [cx, cy] = args.vector(fn, "centre", centre), [tx, ty] = args.vector(fn, "translation", translation);
  args.number(fn, "radius", radius);
  const f = rt.filter(fn, filter, world);
  if (!rt.m._jostle_circle_cast(p, rt.vector(cx, cy), radius, rt.vector(tx, ty, 1), f, rt.out)) {
    rt.check(fn, !rt.failed());
    return null;
  }
  return castHit(world, rt.out);
}

/// moveAndSlide, or roundedMoveAndSlide when fn says so.
export function moveAndSlide(world, centre, half, radius, translation, filter, fn) {
  const p = world.live(fn), rt = world.rt, m = rt.m, size = rt.layout.move_hit.size;
  const [cx, cy] = args.vector(fn, "centre", centre), [hw, hh] = args.vector(fn, "half", half);
  const [tx, ty] = args.vector(fn, "translation", translation);
  if (fn !== "moveAndSlide") args.number(fn, "radius", radius);
  const newCentre = rt.out;
  const [at, count] = rt.many(fn, size, (out, capacity) => {
    const c = rt.vector(cx, cy), h = rt.vector(hw, hh, 1), t = rt.vector(tx, ty, 2), f = rt.filter(fn, filter, world);
    return fn === "moveAndSlide" ? m._jostle_move_and_slide(p, c, h, t, f, newCentre, out, capacity)
                                 : m._jostle_rounded_move_and_slide(p, c, h, radius, t, f, newCentre, out, capacity);
  });
  const L = rt.layout.move_hit, hits = new Array(count);
  for (let i = 0; i < count; i++)
    hits[i] = {body: world.bodyAt(at + i * size + L.body), normal: rt.vec(at + i * size + L.normal)};
  return {centre: rt.vec(newCentre), hits};
}
