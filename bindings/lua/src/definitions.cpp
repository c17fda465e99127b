// Fields of definition tables by their descriptions (definitions.hpp).
#include "definitions.hpp"

namespace jostle::lua {

// The names of each enum are in the order of its values: 0, 1, 2.
BodyType bodyTypeOf(int option) {
    return static_cast<BodyType>(option);
}

Solver solverOf(int option) {
    return static_cast<Solver>(option);
}

FrictionMix frictionMixOf(int option) {
    return static_cast<FrictionMix>(option);
}

bool readField(const Fields& fields, const properties::Property& property, BodyType& out) {
    int option = 0;
    if (!fields.option(property.name, option, kTypeNames))
        return false;
    out = bodyTypeOf(option);
    return true;
}

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

bool readField(const Fields& fields, const properties::Property& property, Solver& out) {
    int option = 0;
    if (!fields.option(property.name, option, kSolverNames))
        return false;
    out = solverOf(option);
    return true;
}

bool readField(const Fields& fields, const properties::Property& property, FrictionMix& out) {
    int option = 0;
    if (!fields.option(property.name, option, kFrictionMixNames))
        return false;
    out = frictionMixOf(option);
    return true;
}

bool readField(const Fields&, const properties::Property&, void*&) {
    return false;
}

bool pushField(lua_State* L, BodyType type) {
    lua_pushstring(L, kTypeNames[static_cast<int>(type)]);
    return true;
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

bool pushField(lua_State* L, Solver solver) {
    lua_pushstring(L, kSolverNames[static_cast<int>(solver)]);
    return true;
}

bool pushField(lua_State* L, FrictionMix mix) {
    lua_pushstring(L, kFrictionMixNames[static_cast<int>(mix)]);
    return true;
}

bool pushField(lua_State*, void*) {
    return false;
}

} // namespace jostle::lua
