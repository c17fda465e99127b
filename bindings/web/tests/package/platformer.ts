// A small platformer level played against the npm package as a game would, typed: a
// character walks, picks up a coin (a sensor), jumps through a one-way platform from
// below and lands on it, walks off onto the floor and onto a lift, which carries it up.
// play() returns what happened; the runners (esm.mjs, cjs.cjs) check it.
import type { Body, DebugDraw, Jostle, World } from "jostle";

export interface Played {
  coinFrame: number; // the frame the coin's sensor event came, -1 if never
  landedOnPlatformFrame: number; // the first frame the character stood on the platform
  onLiftFrame: number; // the first frame it stood on the lift
  rise: number; // how far the lift carried it up in a second at 40 units a second
  liftSpeedUnderFeet: number; // ground().velocity.y while riding
  stateHash: string; // the world's at the end: the same bits in every runner
}

export const DT = 1 / 60;

export function level(jostle: Jostle): { world: World; hero: Body; coin: Body; platform: Body; lift: Body } {
  // y grows downward: the floor's top is at y = 160, a gap in it at x 304..352 holds the lift.
  const world = jostle.createWorld({ gravity: [0, 800] });
  world.createTileMap({ x: 0, y: 160, tile: 16, rows: ["###################...##########"] });
  const hero = world.createBody({ x: 32, y: 150, hw: 6, hh: 10, character: true, userData: "hero" });
  const coin = world.createBody({ type: "static", x: 96, y: 150, hw: 4, hh: 4, sensor: true, userData: "coin" });
  const platform = world.createBody({ type: "static", x: 200, y: 112, hw: 32, hh: 4, oneWay: [0, -1] });
  const lift = world.createBody({ type: "kinematic", x: 328, y: 166, hw: 24, hh: 6 });
  return { world, hero, coin, platform, lift };
}

export function play(jostle: Jostle): Played {
  const { world, hero, coin, platform, lift } = level(jostle);
  const played: Played = { coinFrame: -1, landedOnPlatformFrame: -1, onLiftFrame: -1, rise: 0,
                           liftSpeedUnderFeet: 0, stateHash: "" };
  let jumped = false;
  for (let frame = 0; frame < 600 && played.onLiftFrame < 0; frame++) {
    const ground = hero.ground;
    hero.walkSpeed = 80;
    if (!jumped && ground !== null && hero.position.x >= 150) {
      hero.setVelocity(hero.velocity.x, -360); // a jump: 81 units high, the platform's top is 52
      jumped = true;
    }
    world.step(DT);
    for (const event of world.sensorBegins())
      if (event.sensor === coin && event.visitor === hero && played.coinFrame < 0) played.coinFrame = frame;
    const under = hero.ground;
    if (under?.body === platform && played.landedOnPlatformFrame < 0) played.landedOnPlatformFrame = frame;
    if (under?.body === lift && hero.position.x > 320) played.onLiftFrame = frame;
  }
  // Stand on the lift and ride it up for a second.
  hero.walkSpeed = 0;
  world.step(DT);
  const before = hero.position.y;
  lift.setVelocity(0, -40);
  for (let frame = 0; frame < 60; frame++) world.step(DT);
  played.rise = Math.fround(before - hero.position.y); // in float, as C++ subtracts
  played.liftSpeedUnderFeet = hero.ground?.velocity.y ?? 0;
  played.stateHash = world.stateHash();
  // The debug overlay a game draws over its sprites: one shape a body, all in this view
  // (a readonly tuple and an object for its corners, an option left undefined).
  let shapes = 0;
  const overlay: DebugDraw = { line() {}, box() { shapes++; } };
  world.debugDraw(overlay, { viewMin: [-1000, -1000] as const, viewMax: { x: 1000, y: 1000 },
                             markLength: undefined });
  if (shapes !== world.bodyCount) throw new Error(`debugDraw: ${shapes} shapes, ${world.bodyCount} bodies`);
  world.destroy();
  return played;
}
