// luaopen_jostle: what require("jostle") returns.
//
//     local jostle = require("jostle")
//     local world = jostle.newWorld({gravity = {0, 800}})
//     local box = world:newBody({x = 0, y = 0, hw = 10, hh = 10})
//     world:step(1/60)
//
// docs/lua.md is the manual.
#include "binding.hpp"
#include "jostle/version.h"

namespace {

constexpr luaL_Reg kModuleFunctions[] = {
    {"newWorld", jostle::lua::newWorld},
    {"newFixedStep", jostle::lua::newFixedStep},
    {"rgba", jostle::lua::rgba},
#ifdef JOSTLE_LUA_LEVELS
    {"loadTiled", jostle::lua::loadTiled},
    {"loadLdtk", jostle::lua::loadLdtk},
#endif
    {nullptr, nullptr},
};

} // namespace

// The one symbol the module exports: the interpreter looks it up by this name.
extern "C" __attribute__((visibility("default"))) int luaopen_jostle(lua_State* L) {
    using namespace jostle::lua;
    openBody(L);
    openTileMap(L);
    openWorld(L);
    openFixedStep(L);

    lua_createtable(L, 0, 4);
    luaL_setfuncs(L, kModuleFunctions, 0);
    lua_pushliteral(L, JOSTLE_VERSION_STRING);
    lua_setfield(L, -2, "version");
    return 1;
}
