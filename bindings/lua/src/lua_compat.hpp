// The Lua C API as the module uses it, the same for LuaJIT (Lua 5.1's API) and Lua 5.4.
//
// The module is compiled once per interpreter against that interpreter's headers; the
// few calls that differ between 5.1 and 5.4 are wrapped here, so that the other files
// read the same for both.
#pragma once

#include <lua.hpp>

#include <cstdint>

namespace jostle::lua {

/// A full userdata with room for one user value (5.4) or an environment table (5.1).
inline void* newUserdata(lua_State* L, std::size_t size) {
#if LUA_VERSION_NUM >= 504
    return lua_newuserdatauv(L, size, 1);
#else
    return lua_newuserdata(L, size);
#endif
}

/// Sets the user value of the userdata at `index` to the table on top, and pops it.
/// (5.1 calls it the userdata's environment, and it must be a table: it always is here.)
inline void setUserValue(lua_State* L, int index) {
#if LUA_VERSION_NUM >= 504
    lua_setiuservalue(L, index, 1);
#else
    lua_setfenv(L, index);
#endif
}

/// Pushes the user value of the userdata at `index`.
inline void pushUserValue(lua_State* L, int index) {
#if LUA_VERSION_NUM >= 504
    lua_getiuservalue(L, index, 1);
#else
    lua_getfenv(L, index);
#endif
}

inline std::size_t rawLength(lua_State* L, int index) {
#if LUA_VERSION_NUM >= 502
    return lua_rawlen(L, index);
#else
    return lua_objlen(L, index);
#endif
}

inline int absIndex(lua_State* L, int index) {
    return index > 0 || index <= LUA_REGISTRYINDEX ? index : lua_gettop(L) + index + 1;
}

/// t[key] for the table at `index`, raw, with a key that may exceed an int (5.1's
/// lua_rawgeti takes an int).
inline void rawGetInteger(lua_State* L, int index, std::int64_t key) {
#if LUA_VERSION_NUM >= 503
    lua_rawgeti(L, index, static_cast<lua_Integer>(key));
#else
    index = absIndex(L, index);
    lua_pushnumber(L, static_cast<lua_Number>(key));
    lua_rawget(L, index);
#endif
}

/// t[key] = value on top (popped), raw.
inline void rawSetInteger(lua_State* L, int index, std::int64_t key) {
#if LUA_VERSION_NUM >= 503
    lua_rawseti(L, index, static_cast<lua_Integer>(key));
#else
    index = absIndex(L, index);
    lua_pushnumber(L, static_cast<lua_Number>(key));
    lua_insert(L, -2);
    lua_rawset(L, index);
#endif
}

/// Pushes a whole number: an integer in 5.4 (so that math.type says "integer" and
/// string.format("%d") takes it), a number in 5.1, where every number is a double.
inline void pushWhole(lua_State* L, std::int64_t value) {
#if LUA_VERSION_NUM >= 503
    lua_pushinteger(L, static_cast<lua_Integer>(value));
#else
    lua_pushnumber(L, static_cast<lua_Number>(value));
#endif
}

} // namespace jostle::lua
