// A fixed time step (docs/fixed-step.md): variable frame times turned into a whole number
// of steps of one dt, and where to draw each body between the last two steps.
import * as args from "./args.js";

export class FixedStep {
  constructor(jostle, dt, maxStepsPerFrame) {
    const fn = "createFixedStep", rt = jostle.rt;
    args.number(fn, "dt", dt);
    args.integer(fn, "maxStepsPerFrame", maxStepsPerFrame);
    this.rt = rt;
    this.pointer = rt.m._jostle_fixed_step_create(dt, maxStepsPerFrame);
    rt.check(fn, this.pointer !== 0, "FixedStep");
  }

  live(fn) {
    if (this.pointer === null) throw new Error(`${fn}: the fixed step was destroyed`);
    return this.pointer;
  }

  /// Adds a frame's time (seconds) and returns how many steps of dt to take now.
  advance(frameSeconds) {
    const fn = "advance";
    args.number(fn, "frameSeconds", frameSeconds);
    const steps = this.rt.m._jostle_fixed_step_advance(this.live(fn), frameSeconds);
    return this.rt.got(fn, steps, "FixedStep::advance");
  }

  /// advance, then world.step(dt) that many times, calling afterStep() (if given) after
  /// each: where a game reads the step's events (a world's events are the last step's).
  /// Returns the steps taken.
  update(world, frameSeconds, afterStep) {
    const fn = "update";
    args.number(fn, "frameSeconds", frameSeconds);
    if (afterStep === undefined || afterStep === null) {
      const steps = this.rt.m._jostle_fixed_step_update(this.live(fn), world.live(fn), frameSeconds);
      world.jostle.rethrow();
      return this.rt.got(fn, steps, "FixedStep::advance");
    }
    args.func(fn, "afterStep", afterStep);
    world.live(fn); // checked before the clock counts the frame
    const steps = this.rt.got(fn, this.rt.m._jostle_fixed_step_advance(this.live(fn), frameSeconds),
                              "FixedStep::advance");
    // FixedStep::takeSteps' loop, here so that what afterStep throws stops it at once.
    for (let i = 0; i < steps; i++) {
      if (i === steps - 1) this.rememberPositions(world);
      world.step(this.dt);
      afterStep();
    }
    return steps;
  }

  /// Keeps where every body of `world` is now, for drawPosition: update calls it before the
  /// last step it takes; a game that steps by hand (advance, then world.step) calls it
  /// before the last step of a frame.
  rememberPositions(world) {
    const fn = "rememberPositions";
    this.rt.check(fn, this.rt.m._jostle_fixed_step_remember_positions(this.live(fn), world.live(fn)));
  }

  /// How far the time left over reaches towards the next step, in [0, 1).
  get alpha() { return this.rt.m._jostle_fixed_step_alpha(this.live("alpha")); }
  get dt() { return this.rt.m._jostle_fixed_step_dt(this.live("dt")); }
  get maxStepsPerFrame() { return this.rt.m._jostle_fixed_step_max_steps_per_frame(this.live("maxStepsPerFrame")); }
  /// The seconds the last advance dropped because of the cap.
  get droppedSeconds() { return this.rt.m._jostle_fixed_step_dropped_seconds(this.live("droppedSeconds")); }

  /// Where to draw `body` now, between its last two steps by alpha: {x, y}.
  drawPosition(body) {
    const fn = "drawPosition", rt = this.rt, world = body.world;
    rt.m._jostle_fixed_step_draw_position(rt.out, this.live(fn), world.live(fn), rt.handle(body));
    const v = rt.vec(rt.out);
    if (v.x === 0 && v.y === 0) rt.check(fn, !rt.failed());
    return v;
  }

  /// drawPosition of every body, in the order of world.bodies(), into `out` as
  /// world.readPositions does; returns how many bodies there are.
  readDrawPositions(world, out) {
    const fn = "readDrawPositions", rt = this.rt, m = rt.m;
    args.floats(fn, "out", out);
    const capacity = out.length >> 1, at = rt.bufferOf(8 * Math.max(capacity, 1));
    const count = m._jostle_fixed_step_read_draw_positions(this.live(fn), world.live(fn), at, capacity);
    out.set(rt.floatsAt(at, 2 * Math.min(count, capacity)));
    return count;
  }

  /// Forgets the time left over and where bodies were before the last step (after a
  /// pause, a level load or a restored snapshot).
  reset() { this.rt.check("reset", this.rt.m._jostle_fixed_step_reset(this.live("reset"))); }

  destroy() {
    this.rt.m._jostle_fixed_step_destroy(this.live("destroy"));
    this.pointer = null;
  }
}
