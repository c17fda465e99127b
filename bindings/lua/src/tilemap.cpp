// world:newTileMap and the TileMap methods. Columns and rows are counted from 0, as in
// C++ and scene files: tile (column, row) covers x + column × tile to x + (column + 1) ×
// tile. So the string rows[1] of the definition is row 0.
#include "binding.hpp"
#include "body_properties.hpp"
#include "definitions.hpp"
#include "tile_rows.hpp"

#include <cstdio>
#include <cstring>
#include <optional>

namespace jostle::lua {

namespace {

constexpr int kMaxCoordinate = 0x7FFFFFFF;

TileMapHandle& checkMap(lua_State* L, int index, const char* where) {
    auto* map = static_cast<TileMapHandle*>(luaL_testudata(L, index, kTileMapType));
    if (!map)
        raise(L, where, "expected a TileMap as self (call it with a colon: map:method()), got %s",
              typeName(L, index));
    if (!map->world->data)
        raise(L, where, "the map's world was destroyed");
    if (!map->world->data->world.isValid(map->id))
        raise(L, where, "the map was destroyed");
    return *map;
}

/// Checks the rows table at `rows`: an array of strings. What the strings must be is
/// tile_rows.hpp's, checked once they are copied (worldNewTileMap).
void checkRows(lua_State* L, int rows, const char* where) {
    if (lua_type(L, rows) != LUA_TTABLE)
        raise(L, where, "rows: expected an array of strings, got %s", typeName(L, rows));
    const std::size_t count = rawLength(L, rows);
    for (std::size_t i = 1; i <= count; ++i) {
        rawGetInteger(L, rows, static_cast<std::int64_t>(i));
        if (lua_type(L, -1) != LUA_TSTRING)
            raise(L, where, "rows[%d]: expected a string, got %s", static_cast<int>(i),
                  typeName(L, -1));
        lua_pop(L, 1);
    }
}

using properties::kTileMapFields;

/// What newTileMap reads besides the rows: the settings of TileMapDef, by its table, held
/// apart from a TileMapDef, whose rows have a destructor (definitions.hpp).
using MapSettings = Values<std::size(kTileMapFields)>;

int worldNewTileMap(lua_State* L) {
    const char* where = "World:newTileMap";
    WorldHandle& handle = checkWorldHandle(L, 1, where);
    requireChangeable(L, *handle.data, where);
    checkTable(L, 2, where, "def");
    const Fields fields(L, 2, where);
    // The map's settings but a pointer (userData: a game keys its own table by the map),
    // and its rows.
    static constexpr auto kNames =
        Names<std::size(kTileMapFields) + 1>().addAll(kTileMapFields).add("rows");
    fields.allowOnly(kNames.data());
    MapSettings settings = defaultsOf(kTileMapFields);
    readValues(fields, settings, kTileMapFields,
               [&](const auto& field, const properties::Value& value, bool given) {
                   const char* name = field.property->name;
                   if (!given && field.property->required)
                       raise(L, where, "missing field \"%s\"", name);
                   // A map's tile at once: a map of tiles of no size has no rows to check.
                   if (field.property == &properties::kTile && !(std::get<float>(value) > 0.0f))
                       fields.fail(name, "must be > 0");
               });
    fields.push("rows");
    if (lua_isnil(L, -1))
        raise(L, where, "missing field \"rows\"");
    const int rows = lua_gettop(L);
    checkRows(L, rows, where);
    const std::size_t rowCount = rawLength(L, rows);
    luaL_checkstack(L, 4, "jostle: World:newTileMap");

    char message[kMessageSize];
    bool bad = false;
    TileMapId id;
    const bool ran = attempt(message, [&] {
        TileMapDef def;
        setValues(def, settings, kTileMapFields);
        def.rows.reserve(rowCount);
        for (std::size_t i = 1; i <= rowCount; ++i) {
            // Raw reads of strings checked above: these calls neither allocate nor raise.
            rawGetInteger(L, rows, static_cast<std::int64_t>(i));
            std::size_t length = 0;
            const char* text = lua_tolstring(L, -1, &length);
            def.rows.emplace_back(text, length);
            lua_pop(L, 1);
        }
        // createTileMap's checks, in its order, a problem of the rows told in Lua's
        // counting (rows[1] is the first row, rows[1]:sub(1, 1) its first tile).
        std::optional<FieldError> problem = checkTileMapDef(def);
        if (problem && problem->field.starts_with("rows")) {
            problem = rowsProblem(def.rows, Notation::Lua);
            if (!problem)
                problem = oneWayRampProblem(def.rows, def.oneWay, Notation::Lua);
        }
        if (!problem && handle.data->world.solver() == Solver::Classic)
            problem = rampProblem(def.rows, Notation::Lua);
        if (problem) {
            bad = true;
            describe(message, *problem);
            return;
        }
        id = createTileMap(handle.data->world, def);
    });
    if (!ran || bad)
        raise(L, where, "%s", message);
    pushUserValue(L, 1);
    pushTileMap(L, -1, &handle, id);
    return 1;
}

// --- Methods ---------------------------------------------------------------------------

/// A map method's column and row, its arguments 2 and 3.
TileCoord checkColumnRow(lua_State* L, const char* where) {
    const auto column = checkWhole(L, 2, where, "column", -kMaxCoordinate, kMaxCoordinate);
    const auto row = checkWhole(L, 3, where, "row", -kMaxCoordinate, kMaxCoordinate);
    return {static_cast<int>(column), static_cast<int>(row)};
}

/// setTile's tile: true (solid) or false (empty), or a tile's character as a string of
/// one ("#", ".", a ramp: setTile in C++ checks which).
char checkTile(lua_State* L, int index, const char* where) {
    if (lua_type(L, index) == LUA_TBOOLEAN)
        return lua_toboolean(L, index) ? '#' : '.';
    if (lua_type(L, index) != LUA_TSTRING)
        raise(L, where, "tile: expected true, false or a tile's character, got %s",
              typeName(L, index));
    std::size_t length = 0;
    const char* text = lua_tolstring(L, index, &length);
    if (length != 1)
        raise(L, where, "tile: expected one character, got a string of %d",
              static_cast<int>(length));
    return text[0];
}

int mapSetTile(lua_State* L) {
    const char* where = "TileMap:setTile";
    const TileMapHandle& map = checkMap(L, 1, where);
    const TileCoord at = checkColumnRow(L, where);
    const char tile = checkTile(L, 4, where);
    requireChangeable(L, *map.world->data, where);
    guard(L, where, [&] { setTile(map.world->data->world, map.id, at.column, at.row, tile); });
    return 0;
}

/// The tile's character ("#", ".", a ramp's); "." outside the map.
int mapTileOf(lua_State* L) {
    const char* where = "TileMap:tileOf";
    const TileMapHandle& map = checkMap(L, 1, where);
    const TileCoord at = checkColumnRow(L, where);
    char tile = '.';
    guard(L, where, [&] { tile = tileOf(map.world->data->world, map.id, at.column, at.row); });
    lua_pushlstring(L, &tile, 1);
    return 1;
}

int mapIsSolid(lua_State* L) {
    const char* where = "TileMap:isSolid";
    const TileMapHandle& map = checkMap(L, 1, where);
    const TileCoord at = checkColumnRow(L, where);
    bool solid = false;
    guard(L, where, [&] { solid = isSolid(map.world->data->world, map.id, at.column, at.row); });
    lua_pushboolean(L, solid);
    return 1;
}

/// column, row of the tile that holds the point, or nil outside the map.
int mapTileAt(lua_State* L) {
    const char* where = "TileMap:tileAt";
    const TileMapHandle& map = checkMap(L, 1, where);
    const Vec2 point = checkVec2(L, 2, where, "x", "y");
    bool inside = false;
    TileCoord tile;
    guard(L, where, [&] {
        if (const auto found = tileAt(map.world->data->world, map.id, point)) {
            inside = true;
            tile = *found;
        }
    });
    if (!inside) {
        lua_pushnil(L);
        return 1;
    }
    pushWhole(L, tile.column);
    pushWhole(L, tile.row);
    return 2;
}

/// columns, rows
int mapGetSize(lua_State* L) {
    const char* where = "TileMap:getSize";
    const TileMapHandle& map = checkMap(L, 1, where);
    int columns = 0;
    int rows = 0;
    guard(L, where, [&] {
        columns = tileMapColumns(map.world->data->world, map.id);
        rows = tileMapRows(map.world->data->world, map.id);
    });
    pushWhole(L, columns);
    pushWhole(L, rows);
    return 2;
}

/// The map as a definition table that world:newTileMap accepts, with its tiles as they
/// are now.
int mapGetDef(lua_State* L) {
    const char* where = "TileMap:getDef";
    const TileMapHandle& map = checkMap(L, 1, where);
    MapSettings settings;
    int rows = 0;
    guard(L, where, [&] {
        const World& world = map.world->data->world;
        rows = tileMapRows(world, map.id);
        settings = valuesOf(tileMapDef(world, map.id), kTileMapFields);
    });
    lua_createtable(L, 0, 10);
    setValueFields(L, settings, kTileMapFields);

    // The rows, one string each, built with luaL_Buffer from tileOf: no C++ string
    // lives while Lua allocates.
    lua_createtable(L, rows, 0);
    int columns = 0;
    guard(L, where, [&] { columns = tileMapColumns(map.world->data->world, map.id); });
    for (int row = 0; row < rows; ++row) {
        luaL_Buffer buffer;
        luaL_buffinit(L, &buffer);
        for (int column = 0; column < columns; ++column) {
            char tile = '.';
            guard(L, where, [&] { tile = tileOf(map.world->data->world, map.id, column, row); });
            luaL_addchar(&buffer, tile);
        }
        luaL_pushresult(&buffer);
        lua_rawseti(L, -2, row + 1);
    }
    lua_setfield(L, -2, "rows");
    return 1;
}

/// The static bodies the map is made of now, in creation order.
int mapGetBodies(lua_State* L) {
    const char* where = "TileMap:getBodies";
    TileMapHandle& map = checkMap(L, 1, where);
    WorldData& world = *map.world->data;
    guard(L, where, [&] {
        const auto bodies = tileMapBodies(world.world, map.id);
        world.ids.assign(bodies.begin(), bodies.end());
    });
    pushUserValue(L, 1);
    const int env = lua_gettop(L);
    lua_createtable(L, static_cast<int>(world.ids.size()), 0);
    for (std::size_t i = 0; map.world->data && i < map.world->data->ids.size(); ++i) {
        pushBody(L, env, map.world, map.world->data->ids[i]);
        rawSetInteger(L, -2, static_cast<std::int64_t>(i) + 1);
    }
    return 1;
}

int mapDestroy(lua_State* L) {
    const char* where = "TileMap:destroy";
    const TileMapHandle& map = checkMap(L, 1, where);
    requireChangeable(L, *map.world->data, where);
    guard(L, where, [&] { destroyTileMap(map.world->data->world, map.id); });
    return 0;
}

int mapIsDestroyed(lua_State* L) {
    const auto* map = static_cast<TileMapHandle*>(luaL_testudata(L, 1, kTileMapType));
    if (!map)
        raise(L, "TileMap:isDestroyed", "expected a TileMap as self (call it with a colon), got %s",
              typeName(L, 1));
    lua_pushboolean(L, !map->world->data || !map->world->data->world.isValid(map->id));
    return 1;
}

int mapGetWorld(lua_State* L) {
    if (!luaL_testudata(L, 1, kTileMapType))
        raise(L, "TileMap:getWorld", "expected a TileMap as self (call it with a colon), got %s",
              typeName(L, 1));
    pushUserValue(L, 1);
    lua_rawgeti(L, -1, kSlotWorld);
    return 1;
}

int mapToString(lua_State* L) {
    const auto* map = static_cast<const TileMapHandle*>(lua_touserdata(L, 1));
    const bool live = map->world->data && map->world->data->world.isValid(map->id);
    char text[64];
    std::snprintf(text, sizeof text, "jostle.TileMap %u#%u%s", map->id.index, map->id.generation,
                  live ? "" : " (destroyed)");
    lua_pushstring(L, text);
    return 1;
}

constexpr luaL_Reg kMapMethods[] = {
    {"setTile", mapSetTile},     {"tileOf", mapTileOf},   {"isSolid", mapIsSolid},
    {"tileAt", mapTileAt},       {"getSize", mapGetSize}, {"getDef", mapGetDef},
    {"getBodies", mapGetBodies}, {"destroy", mapDestroy}, {"isDestroyed", mapIsDestroyed},
    {"getWorld", mapGetWorld},   {nullptr, nullptr},
};

constexpr luaL_Reg kWorldMapMethods[] = {
    {"newTileMap", worldNewTileMap},
    {nullptr, nullptr},
};

} // namespace

void pushTileMap(lua_State* L, int env, WorldHandle* world, TileMapId id) {
    pushHandle<TileMapHandle>(L, env, kSlotMaps, 'm', kTileMapType, world, id,
                              world->data->world.isValid(id));
}

void registerTileMapMethods(lua_State* L, int worldMethods) {
    lua_pushvalue(L, worldMethods);
    luaL_setfuncs(L, kWorldMapMethods, 0);
    lua_pop(L, 1);
}

void openTileMap(lua_State* L) {
    luaL_newmetatable(L, kTileMapType);
    lua_createtable(L, 0, 11);
    luaL_setfuncs(L, kMapMethods, 0);
    lua_setfield(L, -2, "__index");
    lua_pushcfunction(L, mapToString);
    lua_setfield(L, -2, "__tostring");
    lua_pushliteral(L, "jostle.TileMap");
    lua_setfield(L, -2, "__name");
    lua_pop(L, 1);
}

} // namespace jostle::lua
