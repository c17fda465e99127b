// jostle.loadTiled and jostle.loadLdtk: a level drawn in Tiled or LDtk (docs/levels.md)
// made into a World, and its objects handed back by name with their bodies:
//
//     local world, objects = jostle.loadTiled("level.tmj")
//     for _, o in ipairs(objects) do if o.name == "spawn" then ... end end
#include "binding.hpp"

#ifdef JOSTLE_LUA_LEVELS

#include "jostle/level.hpp"

#include <string>
#include <vector>

namespace jostle::lua {

namespace {

/// Pushes the world of `level` and the list of its objects: {name, type, layer, id, x, y,
/// hw, hh, properties = {...}, body = Body or nil, bodies = {...}}. Returns 2.
int pushLevel(lua_State* L, const Level& level, const char* where) {
    WorldHandle& handle = pushNewWorld(L, level.scene.world, where);
    const int worldIndex = lua_gettop(L);
    std::vector<BodyId> bodies;
    guard(L, where, [&] {
        addTileMaps(handle.data->world, level.scene);
        bodies = addBodies(handle.data->world, level.scene);
    });
    pushUserValue(L, worldIndex);
    const int env = lua_gettop(L);
    lua_createtable(L, static_cast<int>(level.objects.size()), 0);
    for (std::size_t i = 0; i < level.objects.size(); ++i) {
        const LevelObject& o = level.objects[i];
        lua_createtable(L, 0, 11);
        const auto text = [&](const char* key, const std::string& value) {
            lua_pushlstring(L, value.data(), value.size());
            lua_setfield(L, -2, key);
        };
        const auto number = [&](const char* key, double value) {
            lua_pushnumber(L, static_cast<lua_Number>(value));
            lua_setfield(L, -2, key);
        };
        text("name", o.name);
        text("type", o.type);
        text("layer", o.layer);
        number("id", o.id);
        number("x", static_cast<double>(o.x));
        number("y", static_cast<double>(o.y));
        number("hw", static_cast<double>(o.hw));
        number("hh", static_cast<double>(o.hh));
        lua_createtable(L, 0, static_cast<int>(o.properties.size()));
        for (const auto& [name, value] : o.properties) {
            if (const bool* b = std::get_if<bool>(&value))
                lua_pushboolean(L, *b);
            else if (const double* d = std::get_if<double>(&value))
                lua_pushnumber(L, static_cast<lua_Number>(*d));
            else
                lua_pushstring(L, std::get<std::string>(value).c_str());
            lua_setfield(L, -2, name.c_str());
        }
        lua_setfield(L, -2, "properties");
        lua_createtable(L, o.bodyCount, 0);
        for (int k = 0; k < o.bodyCount; ++k) {
            pushBody(L, env, &handle, bodies[static_cast<std::size_t>(o.body + k)]);
            lua_rawseti(L, -2, k + 1);
        }
        lua_rawgeti(L, -1, 1); // the first body, or nil
        lua_setfield(L, -3, "body");
        lua_setfield(L, -2, "bodies");
        lua_rawseti(L, -2, static_cast<int>(i) + 1);
    }
    lua_remove(L, env);
    return 2;
}

} // namespace

// The arguments are checked before any C++ object is made: a Lua error is a longjmp, which
// would skip their destructors.
int loadTiled(lua_State* L) {
    const char* where = "jostle.loadTiled";
    const char* path = luaL_checkstring(L, 1);
    Level level;
    guard(L, where, [&] { level = jostle::loadTiled(path); });
    return pushLevel(L, level, where);
}

int loadLdtk(lua_State* L) {
    const char* where = "jostle.loadLdtk";
    const char* path = luaL_checkstring(L, 1);
    const char* name = luaL_checkstring(L, 2);
    const bool given = !lua_isnoneornil(L, 3);
    if (given) {
        luaL_checktype(L, 3, LUA_TTABLE);
        lua_pushnil(L);
        while (lua_next(L, 3) != 0) {
            if (lua_type(L, -2) != LUA_TNUMBER || lua_type(L, -1) != LUA_TSTRING)
                raise(L, where,
                      "kinds: expected {[value] = \"solid\" | \"oneWay\" | \"none\" | a ramp's "
                      "character}");
            lua_pop(L, 1);
        }
    }
    IntGridKinds kinds;
    if (given) {
        lua_pushnil(L);
        while (lua_next(L, 3) != 0) {
            kinds[static_cast<int>(lua_tointeger(L, -2))] = lua_tostring(L, -1);
            lua_pop(L, 1);
        }
    }
    Level level;
    guard(L, where, [&] { level = jostle::loadLdtk(path, name, kinds); });
    return pushLevel(L, level, where);
}

} // namespace jostle::lua

#endif // JOSTLE_LUA_LEVELS
