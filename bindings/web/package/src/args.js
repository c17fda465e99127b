// The checks of what a game passes, made before anything reaches the module: each throws
// a TypeError that names the method, the argument and what it got ("setVelocity: vx must
// be a finite number, got NaN"). What only the module knows (jostle's own rules: dt > 0,
// a static body does not move, a stale body) it reports itself, through the C API's last
// error, which Runtime.check throws as an Error naming the method.

/// A value as an error message shows it: 3, NaN, undefined, null, "text", an array...
export function describe(value) {
  switch (typeof value) {
    case "string": return JSON.stringify(value.length > 40 ? value.slice(0, 40) + "..." : value);
    case "bigint": return `${value}n`;
    case "symbol": return "a symbol";
    case "function": return "a function";
    case "object": return value === null ? "null" : Array.isArray(value) ? "an array" : "an object";
    default: return String(value);
  }
}

/// A finite number, which the module takes as a 32-bit float: a number past a float's
/// range (±3.4e38) would reach it as an infinity, so it is refused here. Returns it.
export function number(fn, name, value) {
  if (typeof value !== "number" || !Number.isFinite(value))
    throw new TypeError(`${fn}: ${name} must be a finite number, got ${describe(value)}`);
  if (!Number.isFinite(Math.fround(value)))
    throw new TypeError(`${fn}: ${name} must be a finite number, got ${value}, past a 32-bit float (±3.4e38)`);
  return value;
}

/// An integer in [min, max]. Returns it.
export function integer(fn, name, value, min = -0x80000000, max = 0x7fffffff) {
  if (typeof value !== "number" || !Number.isInteger(value) || value < min || value > max)
    throw new TypeError(`${fn}: ${name} must be an integer in [${min}, ${max}], got ${describe(value)}`);
  return value;
}

/// Filter bits (or a colour): 32 of them, as an integer in [0, 2^32) or as JavaScript's
/// bitwise operators give them, signed (`~ENEMY` is -5 for ENEMY = 4). Returns them
/// unsigned.
export function bits(fn, name, value) {
  if (!isBits(value))
    throw new TypeError(`${fn}: ${name} must be 32 bits: an integer in [0, 4294967295], or a bitwise result, got ${describe(value)}`);
  return value >>> 0;
}

/// Whether `value` is 32 bits as bits() takes them.
function isBits(value) {
  return Number.isInteger(value) && value >= -0x80000000 && value <= 0xffffffff;
}

export function boolean(fn, name, value) {
  if (typeof value !== "boolean")
    throw new TypeError(`${fn}: ${name} must be true or false, got ${describe(value)}`);
  return value;
}

/// A vector: {x, y} or [x, y] of finite numbers. Returns [x, y].
export function vector(fn, name, value) {
  if (Array.isArray(value) && value.length === 2)
    return [number(fn, `${name}[0]`, value[0]), number(fn, `${name}[1]`, value[1])];
  if (typeof value === "object" && value !== null && !Array.isArray(value))
    return [number(fn, `${name}.x`, value.x), number(fn, `${name}.y`, value.y)];
  throw new TypeError(`${fn}: ${name} must be a vector, {x, y} or [x, y], got ${describe(value)}`);
}

/// An object (not null, not an array). Returns it.
export function object(fn, name, value) {
  if (typeof value !== "object" || value === null || Array.isArray(value))
    throw new TypeError(`${fn}: ${name} must be an object, got ${describe(value)}`);
  return value;
}

export function func(fn, name, value) {
  if (typeof value !== "function")
    throw new TypeError(`${fn}: ${name} must be a function, got ${describe(value)}`);
  return value;
}

/// A Float32Array to read into. Returns it.
export function floats(fn, name, value) {
  if (!(value instanceof Float32Array))
    throw new TypeError(`${fn}: ${name} must be a Float32Array, got ${describe(value)}`);
  return value;
}

/// A definition (a scene, a body, a tile map) as JSON for the module's scene loader.
/// JSON.stringify would turn NaN and the infinities into null and leave out undefined,
/// so that the loader would see a null or nothing where the game wrote a number; so
/// every value is checked first, and a bad one is named by its place as the loader names
/// places ("radius", "bodies[3].hw", "gravity[1]"): "createBody: radius: expected a
/// finite number, got NaN". Leave a field out for its default: undefined is refused.
/// Vectors may be {x, y} as well as [x, y].
export function json(fn, value) {
  const problem = jsonProblem(value, []);
  if (problem !== null) {
    let place = "";
    for (const key of problem.place.reverse())
      place += typeof key === "number" ? `[${key}]`
             : (place === "" ? "" : ".") + (/^[A-Za-z_][A-Za-z0-9_]*$/.test(key) ? key : JSON.stringify(key));
    throw new TypeError(`${fn}: ${place === "" ? "" : place + ": "}${problem.what}`);
  }
  return JSON.stringify(value, forTheLoader);
}

/// json()'s replacer: what a definition takes beyond what the scene loader reads, written
/// as it reads it. A vector given as jostle gives them, {x, y} (numbers, no other key), is
/// [x, y]; bit fields as JavaScript's bitwise operators give them (~ENEMY), unsigned, as
/// bits() takes them.
function forTheLoader(key, value) {
  if ((key === "mask" || key === "category") && isBits(value)) return value >>> 0;
  if (value === null || typeof value !== "object" || Array.isArray(value) ||
      typeof value.x !== "number" || typeof value.y !== "number")
    return value;
  const keys = Object.keys(value);
  return keys.length === 2 ? [value.x, value.y] : value;
}

/// What JSON.stringify would not write as it is, in `value`: {place: the keys and
/// indices that lead to it, last first; what: the words of the error}, or null.
/// (`within`: the objects around it, for a value that contains itself.)
function jsonProblem(value, within) {
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
          if ((problem = jsonProblem(value[i], within)) !== null) problem.place.push(i);
      } else {
        for (const key of Object.keys(value))
          if ((problem = jsonProblem(value[key], within)) !== null) {
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
      return {place: [], what: `expected a number, string, boolean, array or object, got ${describe(value)}`};
  }
}
