// jostle for JavaScript and TypeScript: 2D collision detection and response for games
// (docs/javascript.md). Every method checks its arguments: a wrong kind throws a TypeError
// naming the method and the argument; what only jostle knows (a stale body, dt <= 0, a
// static body set moving) throws an Error naming the method, in the C API's words.

/** A vector as jostle gives it. */
export interface Vec2 {
  x: number;
  y: number;
}

/** A vector as jostle takes it: {x, y} or [x, y]. */
export type VecLike = Vec2 | readonly [number, number];

export type BodyType = "static" | "kinematic" | "dynamic";

/** How a body moved by Body.move answers a body in its way (bump.lua's responses). */
export type Response = "slide" | "touch" | "cross" | "bounce" | "ignore";

/**
 * A body as a scene file describes it (docs/scene-format.md): every field optional but
 * hw and hh, checked as the scene loader checks a file's.
 */
export interface BodyDef {
  type?: BodyType;
  /** The centre. */
  x?: number;
  y?: number;
  /** Half width and half height, > 0. */
  hw: number;
  hh: number;
  /** Velocity, units per second; 0 for a static body. */
  vx?: number;
  vy?: number;
  /** In [0, 1], default 0; a pair bounces with the larger. */
  bounce?: number;
  /** In [0, 1], default 0.5; a pair rubs with the smaller. */
  friction?: number;
  /** > 0 to set it (then no density); by default density * area. */
  mass?: number;
  /** > 0, default 1; area is 4 * hw * hh. */
  density?: number;
  /** Default 1; 0 floats, -1 falls up. */
  gravityScale?: number;
  /** >= 0, default 0: velocity /= 1 + damping * dt each step. */
  damping?: number;
  /** Also swept against dynamic bodies (fast small bodies). */
  bullet?: boolean;
  /** A one-way platform's blocking normal: [0, -1] stops bodies from above in a y-down world. */
  oneWay?: VecLike;
  /** The filter categories it belongs to, default 1. */
  category?: number;
  /** The categories it collides with, default 0xFFFFFFFF. */
  mask?: number;
  /** Detects overlaps (sensor events), never pushes nor is pushed. */
  sensor?: boolean;
  /** A character: walks, stands on slopes, rides platforms (docs/characters.md). */
  character?: boolean;
  /** A character's friction on walls and ceilings, default 0. */
  wallFriction?: number;
  /** The steepest floor a character stands on, in degrees, default 60. */
  floorAngle?: number;
  /** How far down a character keeps to the ground over a crest or down a step. */
  snapDown?: number;
  /** How far a character is nudged round a corner it clips. */
  cornerCorrection?: number;
  /** The highest step a character walks up. */
  stepUp?: number;
  /** Rounds the box: hw == hh == radius is a circle, hw == radius < hh a capsule. */
  radius?: number;
  /** A ramp: the corner the slope cuts away ([1, -1]...). */
  slope?: VecLike;
  /** With a slope: the sloped face alone, a one-sided line. */
  segment?: boolean;
  /** A conveyor's surface velocity, for friction. */
  surfaceVelocity?: VecLike;
  /** Yours: any value, kept on the Body. */
  userData?: unknown;
}

/** A body's definition as Body.def() gives it: its vectors as [x, y]. */
export interface BodyDefNow extends BodyDef {
  oneWay?: readonly [number, number];
  slope?: readonly [number, number];
  surfaceVelocity?: readonly [number, number];
}

/** A tile map as a scene file describes it (docs/tilemaps.md). */
export interface TileMapDef {
  /** The corner of tile (0, 0) with the smallest x and y. */
  x?: number;
  y?: number;
  /** The side of a square tile, > 0. */
  tile: number;
  /** The tiles, top row first: "#" solid, "." empty, a ramp's character ("/", "\\", "r", "R"...). */
  rows: readonly string[];
  friction?: number;
  bounce?: number;
  category?: number;
  mask?: number;
  /** [0, -1]: jump-through platforms in a y-down world. */
  oneWay?: VecLike;
  /** Water, lava, a trigger zone drawn in tiles. */
  sensor?: boolean;
  /** Yours: any value, kept on the TileMap. */
  userData?: unknown;
}

/** The classic model's switches, all off by default. */
export interface ClassicOptions {
  /** Impulses shared by inverse mass, momentum conserved. */
  mass: boolean;
  /** Friction takes away at most friction * the normal velocity change. */
  coulomb: boolean;
  /** Dynamic bodies are swept and cannot tunnel through walls. */
  ccd: boolean;
}

/** The physical model's settings (docs/physical-model.md). */
export interface PhysicalOptions {
  /** In [1, 1000], default 4. */
  velocityIterations: number;
  /** In [0, 1000], default 3. */
  positionIterations: number;
  /** In [0, 0.5], default 0.01 (a fraction of half extents). */
  slop: number;
  /** In (0, 1], default 0.2. */
  correction: number;
  /** >= 0; 0 (the default): 2 |gravity| dt. */
  restitutionThreshold: number;
  frictionMix: "min" | "geometricMean";
  /** In [1, 65536], default 64: bounds a step's memory. */
  maxContactsPerBody: number;
}

/** A world as a scene file describes it (docs/scene-format.md). */
export interface SceneDef {
  /** Default [0, 0]; scaled by each body's gravityScale. */
  gravity?: VecLike;
  /** The largest speed of a dynamic body, > 0; none by default. */
  maxVelocity?: number;
  solver?: "classic" | "physical";
  classic?: Partial<ClassicOptions>;
  physical?: Partial<PhysicalOptions>;
  /** Bodies at rest fall asleep (physical model, default on). */
  sleeping?: boolean;
  tilemaps?: readonly TileMapDef[];
  bodies?: readonly BodyDef[];
}

/** Which bodies a query reports; every field optional. */
export interface QueryFilter {
  /** The categories to report, default 0xFFFFFFFF. */
  mask?: number;
  /** The query's own category, default 0xFFFFFFFF. */
  category?: number;
  /** Default false. */
  includeSensors?: boolean;
  /** A body never reported (the character doing the query). */
  ignore?: Body | null;
}

/** Two bodies that started or stopped touching. */
export interface ContactEvent {
  /** The body created first. */
  a: Body;
  b: Body;
  /** Unit, from b towards a. */
  normal: Vec2;
  /** Begin: how fast they met along the normal (>= 0); end: 0. */
  approachSpeed: number;
  /** Begin: where they touch; end: {0, 0}. */
  point: Vec2;
}

export interface SensorEvent {
  sensor: Body;
  visitor: Body;
}

/** A body squeezed between a moving kinematic body and something that would not give. */
export interface CrushEvent {
  body: Body;
  /** The kinematic body pushing. */
  by: Body;
  /** What is on the other side. */
  against: Body;
}

/** A pair about to collide, as the solver sees it before it responds. */
export interface Collision {
  a: Body;
  b: Body;
  /** Unit, from b towards a. */
  normal: Vec2;
  /** How deep they overlap; negative for a pair that will meet within the step. */
  depth: number;
  /** The pair's bounce: change it for this pair and step. */
  bounce: number;
  /** The pair's friction: change it for this pair and step. Unless it is lowered, a
   * character keeps its firm footing on a slope it stands on. */
  friction: number;
}

export interface Touching {
  /** Below it, where gravity pulls. */
  floor: boolean;
  ceiling: boolean;
  wallLeft: boolean;
  wallRight: boolean;
}

export interface Ground {
  /** The body under it. */
  body: Body;
  /** The push of the ground: against gravity. */
  normal: Vec2;
  /** The ground's velocity now: what a rider moves with. */
  velocity: Vec2;
}

export interface ContactInfo {
  other: Body;
  /** Unit, from other towards the body. */
  normal: Vec2;
  point: Vec2;
  /** The normal impulse between them in the last step. */
  impulse: number;
}

export interface RayHit {
  body: Body;
  /** On the face it meets. */
  point: Vec2;
  /** The outward normal of the surface, against the ray. */
  normal: Vec2;
  /** In [0, 1]. */
  fraction: number;
}

export interface CastHit {
  body: Body;
  /** Where the cast shape's centre stops, touching the body. */
  centre: Vec2;
  /** Unit, from the body towards the shape. */
  normal: Vec2;
  /** The fraction of the translation travelled, in [0, 1]. */
  fraction: number;
}

export interface MoveAndSlideResult {
  /** Where the box ends up. */
  centre: Vec2;
  /** The bodies met, in the order met. */
  hits: { body: Body; normal: Vec2 }[];
}

export interface MoveCollision {
  other: Body;
  response: Response;
  /** Unit, from other towards the moved body. */
  normal: Vec2;
  /** The moved body's centre when it touched other. */
  touch: Vec2;
  /** When, as a fraction of the whole move, in [0, 1]. */
  time: number;
  otherCentre: Vec2;
  otherHalf: Vec2;
}

export interface MoveResult {
  /** Where the body is now. */
  x: number;
  y: number;
  collisions: MoveCollision[];
}

/** Where the last step's time went, in milliseconds, stage by stage. */
export interface StepProfile {
  step: number;
  [stage: string]: number;
}

/**
 * A body of a world: a handle the module checks at every call. Once the body is
 * destroyed, every call throws ("position: stale BodyId (the body was destroyed)").
 */
export class Body {
  readonly world: World;
  /** Yours: any value (createBody's def.userData). */
  userData: unknown;
  /** True while the body exists. */
  readonly valid: boolean;
  type: BodyType;
  /** Its centre. */
  get position(): Vec2;
  set position(value: VecLike);
  get velocity(): Vec2;
  set velocity(value: VecLike);
  get halfExtents(): Vec2;
  set halfExtents(value: VecLike);
  bounce: number;
  friction: number;
  mass: number;
  gravityScale: number;
  damping: number;
  bullet: boolean;
  get oneWay(): Vec2;
  set oneWay(value: VecLike);
  category: number;
  mask: number;
  sensor: boolean;
  character: boolean;
  wallFriction: number;
  floorAngle: number;
  get surfaceVelocity(): Vec2;
  set surfaceVelocity(value: VecLike);
  cornerCorrection: number;
  stepUp: number;
  snapDown: number;
  /** A character's speed along what it stands on. */
  walkSpeed: number;
  readonly awake: boolean;
  /** How far the last step pushed it out of what it overlapped. */
  readonly separation: Vec2;
  /** The sides it touched at the end of the last step. */
  readonly touching: Touching;
  /** What a character stands on, or null in the air. */
  readonly ground: Ground | null;
  /** The tile map the body is part of, or null. */
  readonly tileMap: TileMap | null;
  setPosition(x: number, y: number): void;
  setVelocity(vx: number, vy: number): void;
  setHalfExtents(hw: number, hh: number): void;
  /** Sets the mass from a density (mass = density * 4 * hw * hh). */
  setDensity(density: number): void;
  /** Adds a force (mass * units / s²) for the next step. */
  applyForce(fx: number, fy: number): void;
  /** Changes the velocity by impulse / mass at once. */
  applyImpulse(ix: number, iy: number): void;
  wake(): void;
  /** Falls through one-way platforms for `seconds`. */
  dropThrough(seconds: number): void;
  /** The bodies it touched at the end of the last step. */
  contacts(): ContactInfo[];
  isTouching(other: Body): boolean;
  /** Moves the body by (dx, dy) as bump.lua's world:move does; filter answers each body in the way. */
  move(dx: number, dy: number, filter?: ((other: Body) => Response) | null): MoveResult;
  /** Its definition as a scene file's body object, every setting as it is now. */
  def(): BodyDefNow;
  /** Removes it from its world. */
  destroy(): void;
}

/** A tile map: a handle, checked as a body's is. */
export class TileMap {
  readonly world: World;
  /** Yours: any value, kept on this object (createTileMap's def.userData). */
  userData: unknown;
  readonly valid: boolean;
  readonly columns: number;
  readonly rows: number;
  /** Sets a tile inside the map: "#", ".", or a ramp's character. */
  setTile(column: number, row: number, tile: string): void;
  /** The tile's character; "." outside the map. */
  tileOf(column: number, row: number): string;
  /** True if the tile is solid ("#"). */
  isSolid(column: number, row: number): boolean;
  /** The tile that contains the point, or null outside the map. */
  tileAt(point: VecLike): { column: number; row: number } | null;
  /** The static bodies the map is made of now. */
  bodies(): Body[];
  /** Destroys the map and its bodies. */
  destroy(): void;
}

export class World {
  get gravity(): Vec2;
  set gravity(value: VecLike);
  /** Infinity: no clamp. */
  maxVelocity: number;
  solver: "classic" | "physical";
  sleeping: boolean;
  /** 1 in WebAssembly, which is built without threads. */
  readonly workers: number;
  classicOptions: ClassicOptions;
  physicalOptions: PhysicalOptions;
  /** How many bodies there are, tile maps' included. */
  readonly bodyCount: number;
  /** Pairs the last step left out because a body had more than maxContactsPerBody. */
  readonly pairsLeftOut: number;

  /** A body from a scene file's body object. */
  createBody(def: BodyDef): Body;
  /** A tile map from a scene file's tile map object. */
  createTileMap(def: TileMapDef): TileMap;
  /** Every body, tile maps' included, in creation order: the order of the reads. */
  bodies(): Body[];
  /**
   * Every body's centre, x then y, in the order of bodies(), into out (what does not fit
   * is left out); returns how many bodies there are. One call, no garbage.
   */
  readPositions(out: Float32Array): number;
  readVelocities(out: Float32Array): number;
  readHalfExtents(out: Float32Array): number;
  /**
   * Every body's shape, six numbers a body: half width, half height, radius, slope x, slope y,
   * flags (type 0 static, 1 kinematic, 2 dynamic; + 4 sensor, + 8 segment, + 16 awake). A
   * shape is fixed when its body is made: read them when bodies come and go.
   */
  readShapes(out: Float32Array): number;
  /**
   * Draws the world as the engine sees it through the game's renderer: every body in its
   * shape and colour (tile maps' merged boxes among them), and what `options` asks for
   * (docs/debug-draw.md). One call a frame, over the game's sprites.
   */
  debugDraw(draw: DebugDraw, options?: DebugDrawOptions): void;

  /** Advances the world by dt seconds (> 0). */
  step(dt: number): void;
  contactBegins(): ContactEvent[];
  contactEnds(): ContactEvent[];
  sensorBegins(): SensorEvent[];
  sensorEnds(): SensorEvent[];
  crushBegins(): CrushEvent[];
  crushEnds(): CrushEvent[];
  profile(): StepProfile;
  /**
   * Calls callback for every pair the solver is about to respond to: false lets the pair
   * pass through this time; bounce and friction may be changed. null removes it. In the
   * physical model a body's mass is taken when the step first meets it: a mass or type the
   * callback changes for a body met already counts from the next step.
   */
  setPreSolve(callback: ((collision: Collision) => boolean | void) | null): void;

  queryPoint(point: VecLike, filter?: QueryFilter): Body[];
  queryBox(centre: VecLike, half: VecLike, filter?: QueryFilter): Body[];
  queryRect(min: VecLike, max: VecLike, filter?: QueryFilter): Body[];
  rayCast(from: VecLike, to: VecLike, filter?: QueryFilter): RayHit | null;
  rayCastAll(from: VecLike, to: VecLike, filter?: QueryFilter): RayHit[];
  boxCast(centre: VecLike, half: VecLike, translation: VecLike, filter?: QueryFilter): CastHit | null;
  roundedBoxCast(centre: VecLike, half: VecLike, radius: number, translation: VecLike,
                 filter?: QueryFilter): CastHit | null;
  circleCast(centre: VecLike, radius: number, translation: VecLike, filter?: QueryFilter): CastHit | null;
  /** Moves a box as bump.lua does, sliding along what it meets; nothing in the world moves. */
  moveAndSlide(centre: VecLike, half: VecLike, translation: VecLike, filter?: QueryFilter): MoveAndSlideResult;
  roundedMoveAndSlide(centre: VecLike, half: VecLike, radius: number, translation: VecLike,
                      filter?: QueryFilter): MoveAndSlideResult;

  /**
   * This world's body of the same slot and generation as `other`, a Body of another world
   * whose snapshot this one restored (a saved game, a peer's state); null if none is alive.
   */
  adopt(other: Body): Body | null;
  adopt(other: TileMap): TileMap | null;
  /** How many bytes snapshot() writes now: how long an `into` must be. */
  snapshotSize(): number;
  /**
   * Everything that decides the world's future (docs/snapshots.md): a new array, or, given
   * `into` long enough, the front of it (`into.subarray(0, size)`: no new buffer a frame).
   * Given an `into` too short, a new array: keep what it returns, not `into`.
   */
  snapshot(into?: Uint8Array): Uint8Array;
  /**
   * Makes the world what it was when the snapshot was taken: its bytes exactly, as
   * snapshot() returned them. A body made again after it under a handle the game met
   * before is the same object, with its new def's userData.
   */
  restore(snapshot: Uint8Array): void;
  /** A hash of exactly what a snapshot holds, as 16 hexadecimal digits. */
  stateHash(): string;
  /** Frees the world; it and its bodies may not be used after. */
  destroy(): void;
}

/** A fixed time step (docs/fixed-step.md). */
export class FixedStep {
  readonly dt: number;
  readonly maxStepsPerFrame: number;
  /** How far the time left over reaches towards the next step, in [0, 1). */
  readonly alpha: number;
  /** The seconds the last advance dropped because of the cap. */
  readonly droppedSeconds: number;
  /** Adds a frame's time and returns how many steps of dt to take now. */
  advance(frameSeconds: number): number;
  /**
   * advance, then world.step(dt) that many times, calling afterStep() after each (where a
   * game reads the step's events: a world's are the last step's); returns the steps taken.
   */
  update(world: World, frameSeconds: number, afterStep?: (() => void) | null): number;
  /**
   * Keeps where every body is now, for drawPosition: update does it before its last step;
   * a game stepping by hand (advance, then world.step) calls it before a frame's last step.
   */
  rememberPositions(world: World): void;
  /** Where to draw the body now, between its last two steps by alpha. */
  drawPosition(body: Body): Vec2;
  /** drawPosition of every body, as world.readPositions. */
  readDrawPositions(world: World, out: Float32Array): number;
  /** Forgets the time left over and where bodies were (after a pause, a load, a restore). */
  reset(): void;
  destroy(): void;
}

/** An object of a level (docs/levels.md): a spawn point, a door, an enemy. */
export interface LevelObject {
  /** Its name in the editor ("" if none); an LDtk entity's identifier. */
  name: string;
  /** Tiled's class; an LDtk entity's identifier. */
  type: string;
  /** The layer it is on. */
  layer: string;
  /** Tiled's object id. */
  id: number;
  /** Its centre; a point's position. */
  x: number;
  y: number;
  /** Half its width and height (0 for a point). */
  hw: number;
  hh: number;
  /** Its custom properties (LDtk: fields) by name. */
  properties: Record<string, boolean | number | string>;
  /** The body made from it, or null. */
  body: Body | null;
  /** Every body made from it: one, none, or a polygon's sides. */
  bodies: Body[];
}

/** A level read from an editor's file: its world, made, and its objects. */
export interface LoadedLevel {
  world: World;
  objects: LevelObject[];
}

export interface LevelOptions {
  /** What errors call the file, "level.tmj" by default. */
  name?: string;
  /** The texts of the files it names (Tiled's external tilesets, LDtk's levels saved apart), by path. */
  files?: Record<string, string>;
}

/** The loaded module. */
export class Jostle {
  /** "major.minor.patch". */
  readonly version: string;
  /** A world from a scene object or a scene file's text, its tile maps and bodies made too. */
  createWorld(scene?: SceneDef | string): World;
  /** A clock of steps of dt seconds, at most maxStepsPerFrame a frame (default 8). */
  createFixedStep(dt: number, maxStepsPerFrame?: number): FixedStep;
  /**
   * A level drawn in Tiled, from its JSON text (.tmj; XML maps are not read in WebAssembly:
   * export them as JSON), its world made: tile layers as tile maps, objects as bodies.
   */
  loadTiled(text: string, options?: LevelOptions): LoadedLevel;
  /**
   * A level of an LDtk project by its identifier, from the project's text; kinds says what
   * IntGrid values are ("solid", "oneWay", "none" or a ramp's character).
   */
  loadLdtk(text: string, level: string, options?: LevelOptions & { kinds?: Record<number, string> }): LoadedLevel;
}

/**
 * A colour: 0xRRGGBBAA, red, green, blue and opacity 0 to 255 each (cssColour makes it a
 * canvas's style).
 */
export type Colour = number;

/**
 * The game's renderer, as debugDraw calls it, in world units. `line` is required; the
 * others, when absent, are drawn with lines. A fill of opacity 0 is not filled.
 */
export interface DebugDraw {
  line(x1: number, y1: number, x2: number, y2: number, colour: Colour): void;
  /** An axis-aligned box by its centre and half extents. */
  box?(x: number, y: number, hw: number, hh: number, fill: Colour, outline: Colour): void;
  /** A box with corners rounded by `radius`: a circle when hw = hh = radius, a capsule when one is. */
  roundedBox?(x: number, y: number, hw: number, hh: number, radius: number, fill: Colour, outline: Colour): void;
  /** A triangle (a ramp), its corners in order around it. */
  triangle?(x1: number, y1: number, x2: number, y2: number, x3: number, y3: number, fill: Colour, outline: Colour): void;
  /** A point (a contact), `size` wide: a quarter of markLength. */
  point?(x: number, y: number, size: number, colour: Colour): void;
}

/** The colours debugDraw uses; a body's outline is its fill scaled by outlinePercent. */
export interface DebugPalette {
  staticBody?: Colour;
  kinematicBody?: Colour;
  dynamicBody?: Colour;
  /** A sleeping body's fill: its type's colour scaled so, 0 to 100 (55). */
  sleepingPercent?: number;
  /** An outline: its fill scaled so, 0 to 100 (60). */
  outlinePercent?: number;
  bulletOutline?: Colour;
  /** The face a one-way body blocks from. */
  oneWayFace?: Colour;
  contact?: Colour;
  velocity?: Colour;
  /** The sides a dynamic body touched. */
  touching?: Colour;
  gridCell?: Colour;
  gridBox?: Colour;
}

/** What debugDraw draws. */
export interface DebugDrawOptions {
  /** Every body, tile maps' merged boxes among them (true). */
  shapes?: boolean;
  /** Every touching pair: where it touches, and its normal into the body it pushes. */
  contacts?: boolean;
  /** Awake dynamic bodies: a tenth of a second of their motion. */
  velocities?: boolean;
  /** The sides each dynamic body touched in the last step. */
  touching?: boolean;
  /** The broadphase's occupied cells and its moving boxes. */
  grid?: boolean;
  /** The longest a normal, a segment's tick or a point's cross is, in world units (0.25). */
  markLength?: number;
  /** Only what touches this box is drawn (a view); min > max on either axis draws everything. */
  viewMin?: VecLike;
  viewMax?: VecLike;
  palette?: DebugPalette;
}

/** A colour as CSS writes it, "#rrggbbaa", for a canvas's fillStyle and strokeStyle. */
export function cssColour(colour: Colour): string;

export interface LoadOptions {
  /**
   * jostle.wasm: its bytes, a compiled module, its URL or a Response; by default the
   * jostle.wasm beside the package's own file.
   */
  wasm?: BufferSource | WebAssembly.Module | URL | string | Response | PromiseLike<Response>;
}

/** Loads the module. */
export function load(options?: LoadOptions): Promise<Jostle>;
