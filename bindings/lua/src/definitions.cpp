// Fields of definition tables by their descriptions (definitions.hpp).
#include "definitions.hpp"

namespace jostle::lua {

bool readField(const Fields& fields, const properties::Property& property, float& out) {
    if (property.rule == properties::Rule::PositiveOrInfinity)
        return fields.numberOrInfinity(property.name, out);
    return fields.number(property.name, out);
}

bool readField(const Fields& fields, const properties::Property& property, Vec2& out) {
    return fields.vec2(property.name, out);
}

bool readField(const Fields& fields, const properties::Property& property, bool& out) {
    return fields.boolean(property.name, out);
}

bool readField(const Fields& fields, const properties::Property& property, std::uint32_t& out) {
    return fields.bits(property.name, out);
}

bool readField(const Fields& fields, const properties::Property& property, int& out) {
    const properties::Interval& range = property.range;
    return fields.whole(property.name, out, static_cast<int>(range.low),
                        static_cast<int>(range.high));
}

bool readField(const Fields&, const properties::Property&, void*&) {
    return false;
}

bool pushField(lua_State* L, float value) {
    lua_pushnumber(L, static_cast<lua_Number>(value));
    return true;
}

bool pushField(lua_State* L, Vec2 value) {
    lua_createtable(L, 2, 0);
    lua_pushnumber(L, static_cast<lua_Number>(value.x));
    lua_rawseti(L, -2, 1);
    lua_pushnumber(L, static_cast<lua_Number>(value.y));
    lua_rawseti(L, -2, 2);
    return true;
}

bool pushField(lua_State* L, bool value) {
    lua_pushboolean(L, value);
    return true;
}

bool pushField(lua_State* L, std::uint32_t value) {
    pushWhole(L, value);
    return true;
}

bool pushField(lua_State* L, int value) {
    pushWhole(L, value);
    return true;
}

bool pushField(lua_State*, void*) {
    return false;
}

} // namespace jostle::lua
