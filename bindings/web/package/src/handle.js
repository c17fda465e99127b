// What a body and a tile map share: a handle ({index, generation} of jostle.h's ids, and
// the world's serial) that the module checks at every call, and one object a handle
// wherever the module hands it back.

export class Handle {
  constructor(world, index, generation, serial) {
    this.world = world;
    this.index = index;
    this.generation = generation;
    this.serial = serial;
  }

  /// Calls jostle.h's `name`(world, handle, ...rest) and returns what it returns.
  call(fn, name, ...rest) {
    const rt = this.world.rt;
    return rt.m[name](this.world.live(fn), rt.handle(this), ...rest);
  }
}

/// The object of the handle at `at` in the module's memory (null for the null handle):
/// the one `table` (by slot) holds if it is that handle, else a new `Kind`, kept in the
/// table unless its slot holds a newer one.
export function handleAt(world, at, table, Kind) {
  const words = world.rt.m.HEAPU32, index = words[at >> 2], generation = words[(at >> 2) + 1];
  if (generation === 0) return null;
  const known = table[index];
  if (known !== undefined && known.generation === generation) return known;
  const handle = new Kind(world, index, generation, words[(at >> 2) + 2]);
  if (known === undefined || known.generation < generation) table[index] = handle;
  return handle;
}
