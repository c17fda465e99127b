// The C API's tile maps: an array of cells (solid, empty or ramps) made into static bodies.
#include "c_api.hpp"

using namespace jostle;
using namespace jostle::c_api;

extern "C" {

jostle_tile_map_def jostle_default_tile_map_def(void) {
    const TileMapDef defaults;
    jostle_tile_map_def d{}; // no columns, no rows, no cells
    copyToC(defaults, d, properties::kTileMapFields);
    d.internal_cookie = kCookie;
    return d;
}

jostle_tile_map_id jostle_tile_map_create(jostle_world* world, const jostle_tile_map_def* def) {
    return guard(__func__, jostle_tile_map_id{}, [&] {
        World& w = worldOf(world).world;
        return toC(createTileMap(w, toCpp(required(def, "def"))));
    });
}

bool jostle_tile_map_destroy(jostle_world* world, jostle_tile_map_id map) {
    return guard(__func__, false, [&] {
        destroyTileMap(worldOf(world).world, toCpp(map));
        return true;
    });
}

bool jostle_tile_map_is_valid(const jostle_world* world, jostle_tile_map_id map) {
    return guard(__func__, false, [&] { return worldOf(world).world.isValid(toCpp(map)); });
}

jostle_tile_map_id jostle_world_adopt_tile_map(const jostle_world* world, jostle_tile_map_id map) {
    return guard(__func__, jostle_tile_map_id{},
                 [&] { return toC(worldOf(world).world.adopt(toCpp(map))); });
}

bool jostle_tile_map_set_tile(jostle_world* world, jostle_tile_map_id map, int column, int row,
                              bool solid) {
    return guard(__func__, false, [&] {
        setTile(worldOf(world).world, toCpp(map), column, row, solid);
        return true;
    });
}

bool jostle_tile_map_set_tile_char(jostle_world* world, jostle_tile_map_id map, int column, int row,
                                   char tile) {
    return guard(__func__, false, [&] {
        setTile(worldOf(world).world, toCpp(map), column, row, tile);
        return true;
    });
}

char jostle_tile_map_tile_of(const jostle_world* world, jostle_tile_map_id map, int column,
                             int row) {
    return guard(__func__, '\0',
                 [&] { return tileOf(worldOf(world).world, toCpp(map), column, row); });
}

bool jostle_tile_map_is_solid(const jostle_world* world, jostle_tile_map_id map, int column,
                              int row) {
    return guard(__func__, false,
                 [&] { return isSolid(worldOf(world).world, toCpp(map), column, row); });
}

bool jostle_tile_map_tile_at(const jostle_world* world, jostle_tile_map_id map, jostle_vec2 point,
                             int* column, int* row) {
    return guard(__func__, false, [&] {
        const World& w = worldOf(world).world;
        int& c = required(column, "column");
        int& r = required(row, "row");
        const std::optional<TileCoord> tile = tileAt(w, toCpp(map), toCpp(point));
        if (!tile)
            return false;
        c = tile->column;
        r = tile->row;
        return true;
    });
}

int jostle_tile_map_columns(const jostle_world* world, jostle_tile_map_id map) {
    return guard(__func__, 0, [&] { return tileMapColumns(worldOf(world).world, toCpp(map)); });
}

int jostle_tile_map_rows(const jostle_world* world, jostle_tile_map_id map) {
    return guard(__func__, 0, [&] { return tileMapRows(worldOf(world).world, toCpp(map)); });
}

int jostle_tile_map_bodies(const jostle_world* world, jostle_tile_map_id map, jostle_body_id* out,
                           int capacity) {
    return guard(__func__, 0, [&] {
        const World& w = worldOf(world).world;
        checkBuffer(out, capacity);
        return copyOut(tileMapBodies(w, toCpp(map)), out, capacity);
    });
}

jostle_tile_map_id jostle_tile_map_of(const jostle_world* world, jostle_body_id body) {
    return guard(__func__, jostle_tile_map_id{},
                 [&] { return toC(tileMapOf(worldOf(world).world, toCpp(body))); });
}

} // extern "C"
