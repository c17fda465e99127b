// world:snapshot(), world:restore(s) and world:stateHash() (docs/lua.md#snapshots): a
// world's snapshot as a Lua string of its bytes, the same bytes as in C++ and C.
#include "binding.hpp"

#include <cinttypes>
#include <cstdio>

namespace jostle::lua {

namespace {

int worldSnapshot(lua_State* L) {
    const char* where = "World:snapshot";
    WorldData& world = checkWorld(L, 1, where);
    // Into the world's own buffer, reused from one snapshot to the next.
    guard(L, where, [&] {
        world.snapshot.resize(world.world.snapshotSize());
        world.world.snapshot(world.snapshot);
    });
    lua_pushlstring(L, reinterpret_cast<const char*>(world.snapshot.data()), world.snapshot.size());
    return 1;
}

int worldRestore(lua_State* L) {
    const char* where = "World:restore";
    WorldData& world = checkWorld(L, 1, where);
    if (lua_type(L, 2) != LUA_TSTRING)
        raise(L, where, "snapshot: expected a string (from world:snapshot()), got %s",
              typeName(L, 2));
    std::size_t size = 0;
    const char* bytes = lua_tolstring(L, 2, &size);
    guard(L, where, [&] {
        world.world.restore({reinterpret_cast<const std::byte*>(bytes), size});
    });
    return 0;
}

int worldStateHash(lua_State* L) {
    const char* where = "World:stateHash";
    WorldData& world = checkWorld(L, 1, where);
    std::uint64_t hash = 0;
    guard(L, where, [&] { hash = world.world.stateHash(); });
    // 16 hexadecimal digits: LuaJIT's numbers cannot hold 64 bits.
    char text[17];
    std::snprintf(text, sizeof text, "%016" PRIx64, hash);
    lua_pushstring(L, text);
    return 1;
}

constexpr luaL_Reg kSnapshotMethods[] = {
    {"snapshot", worldSnapshot},
    {"restore", worldRestore},
    {"stateHash", worldStateHash},
    {nullptr, nullptr},
};

} // namespace

void registerSnapshotMethods(lua_State* L, int worldMethods) {
    lua_pushvalue(L, worldMethods);
    luaL_setfuncs(L, kSnapshotMethods, 0);
    lua_pop(L, 1);
}

} // namespace jostle::lua
