// A tile map of a world (docs/tilemaps.md): a handle, checked by the module at every call
// as a body's is. Its tiles are the characters of a scene file's rows: "#" solid, "."
// empty, a ramp's character.
import * as args from "./args.js";
import {Handle} from "./handle.js";

export class TileMap extends Handle {
  constructor(world, index, generation, serial) {
    super(world, index, generation, serial);
    /// Yours: any value, kept on this object (createTileMap's def.userData).
    this.userData = undefined;
  }

  /// True while the map exists.
  get valid() {
    const w = this.world;
    return w.pointer !== null && w.rt.m._jostle_tile_map_is_valid(w.pointer, w.rt.handle(this)) !== 0;
  }

  /// Destroys the map and its bodies; what rests on them wakes and falls.
  destroy() { this.world.rt.check("destroy", this.call("destroy", "_jostle_tile_map_destroy"), "destroyTileMap"); }

  get columns() { return this.world.rt.got("columns", this.call("columns", "_jostle_tile_map_columns")); }
  get rows() { return this.world.rt.got("rows", this.call("rows", "_jostle_tile_map_rows")); }

  /// Sets the tile at (column, row), inside the map, to a tile character: "#", "." or a
  /// ramp's ("/", "\\", "7", "F", "r", "R", "L", "l", "c", "C", "D", "d").
  setTile(column, row, tile) {
    const fn = "setTile";
    args.integer(fn, "column", column);
    args.integer(fn, "row", row);
    if (typeof tile !== "string" || tile.length !== 1 || tile.charCodeAt(0) > 127)
      throw new TypeError(`${fn}: tile must be one tile character ("#", ".", "/"...), got ${args.describe(tile)}`);
    this.world.rt.check(fn, this.call(fn, "_jostle_tile_map_set_tile_char", column, row, tile.charCodeAt(0)));
  }

  /// The character of the tile at (column, row); "." outside the map.
  tileOf(column, row) {
    const fn = "tileOf";
    args.integer(fn, "column", column);
    args.integer(fn, "row", row);
    const code = this.call(fn, "_jostle_tile_map_tile_of", column, row);
    this.world.rt.check(fn, code !== 0);
    return String.fromCharCode(code);
  }

  /// True if the tile is solid ("#"; a ramp is not); false outside the map.
  isSolid(column, row) {
    const fn = "isSolid";
    args.integer(fn, "column", column);
    args.integer(fn, "row", row);
    return this.world.rt.got(fn, this.call(fn, "_jostle_tile_map_is_solid", column, row)) !== 0;
  }

  /// The tile that contains `point` ({x, y} or [x, y]): {column, row}, or null outside.
  tileAt(point) {
    const fn = "tileAt", rt = this.world.rt;
    const [x, y] = args.vector(fn, "point", point);
    const at = rt.out;
    if (!this.call(fn, "_jostle_tile_map_tile_at", rt.vector(x, y), at, at + 4)) {
      rt.check(fn, !rt.failed());
      return null;
    }
    return {column: rt.m.HEAP32[at >> 2], row: rt.m.HEAP32[(at >> 2) + 1]};
  }

  /// The static bodies the map is made of now, in creation order.
  bodies() {
    const fn = "bodies", rt = this.world.rt, size = rt.layout.body_id.size;
    const [at, count] = rt.many(fn, size, (out, capacity) => this.call(fn, "_jostle_tile_map_bodies", out, capacity));
    const bodies = new Array(count);
    for (let i = 0; i < count; i++) bodies[i] = this.world.bodyAt(at + i * size);
    return bodies;
  }
}
