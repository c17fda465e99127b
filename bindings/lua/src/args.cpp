// Argument checking and error raising (args.hpp).
#include "args.hpp"

#include "binding.hpp"
#include "notation.hpp"
#include "suggest.hpp"

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>

namespace jostle::lua {

[[noreturn]] void raise(lua_State* L, const char* where, const char* format, ...) {
    luaL_where(L, 1);
    lua_pushstring(L, where);
    lua_pushliteral(L, ": ");
    va_list args;
    va_start(args, format);
    lua_pushvfstring(L, format, args);
    va_end(args);
    lua_concat(L, 4);
    lua_error(L);
    std::abort(); // lua_error does not return
}

void copyMessage(char (&out)[kMessageSize], const char* text) {
    std::snprintf(out, kMessageSize, "%s", text);
}

void describe(char (&out)[kMessageSize], const std::exception& error, bool fromJostle) {
    const char* text = error.what();
    if (!fromJostle) {
        copyMessage(out, text);
        return;
    }
    // "setMass: mass must be > 0": the C++ name goes, the Lua one takes its place; the
    // rule is written in Lua's notation (notation.hpp).
    if (const char* colon = std::strstr(text, ": "))
        text = colon + 2;
    copyInNotation(text, Notation::Lua, out, kMessageSize);
}

void describeCurrentException(char (&out)[kMessageSize]) noexcept {
    try {
        throw;
    } catch (const jostle::Error& error) {
        describe(out, error, true);
    } catch (const std::bad_alloc&) {
        copyMessage(out, "out of memory");
    } catch (const std::exception& error) {
        describe(out, error, false);
    } catch (...) {
        copyMessage(out, "unexpected C++ exception");
    }
}

void describe(char (&out)[kMessageSize], const FieldError& problem) {
    const std::string text = problem.field + ": " + problem.problem;
    copyInNotation(text, Notation::Lua, out, kMessageSize);
}

const char* typeName(lua_State* L, int index) {
    if (lua_type(L, index) == LUA_TUSERDATA && lua_getmetatable(L, index)) {
        static constexpr const char* kNames[] = {kWorldType, kBodyType, kTileMapType,
                                                 kFixedStepType};
        for (const char* name : kNames) {
            luaL_getmetatable(L, name);
            const bool same = lua_rawequal(L, -1, -2) != 0;
            lua_pop(L, 1);
            if (same) {
                lua_pop(L, 1);
                return std::strchr(name, '.') + 1; // "jostle.Body" -> "Body"
            }
        }
        lua_pop(L, 1);
    }
    return luaL_typename(L, index);
}

namespace {

/// The number at `index` as a float, or a Lua error naming `prefix``name`.
float toFloat(lua_State* L, int index, const char* where, const char* prefix, const char* name,
              bool allowInfinity) {
    if (lua_type(L, index) != LUA_TNUMBER)
        raise(L, where, "%s%s: expected a number, got %s", prefix, name, typeName(L, index));
    const double value = static_cast<double>(lua_tonumber(L, index));
    if (allowInfinity && value == std::numeric_limits<double>::infinity())
        return std::numeric_limits<float>::infinity();
    // A double beyond float's range would become infinity: refused like NaN.
    if (!std::isfinite(value) || !std::isfinite(static_cast<float>(value)))
        raise(L, where, "%s%s: must be a finite number", prefix, name);
    return static_cast<float>(value);
}

std::int64_t toWhole(lua_State* L, int index, const char* where, const char* prefix,
                     const char* name, std::int64_t min, std::int64_t max) {
    if (lua_type(L, index) != LUA_TNUMBER)
        raise(L, where, "%s%s: expected a whole number, got %s", prefix, name, typeName(L, index));
    const double value = static_cast<double>(lua_tonumber(L, index));
    if (!(value == std::floor(value)) || !std::isfinite(value))
        raise(L, where, "%s%s: expected a whole number", prefix, name);
    if (value < static_cast<double>(min) || value > static_cast<double>(max)) {
        char range[64];
        std::snprintf(range, sizeof range, "%lld to %lld", static_cast<long long>(min),
                      static_cast<long long>(max));
        raise(L, where, "%s%s: must be from %s", prefix, name, range);
    }
    return static_cast<std::int64_t>(value);
}

bool toBoolean(lua_State* L, int index, const char* where, const char* prefix, const char* name) {
    if (lua_type(L, index) != LUA_TBOOLEAN)
        raise(L, where, "%s%s: expected true or false, got %s", prefix, name, typeName(L, index));
    return lua_toboolean(L, index) != 0;
}

int toOption(lua_State* L, int index, const char* where, const char* prefix, const char* name,
             const char* const* names) {
    index = absIndex(L, index); // the list of names below is pushed on top
    if (lua_type(L, index) == LUA_TSTRING) {
        const char* given = lua_tostring(L, index);
        for (int i = 0; names[i]; ++i)
            if (std::strcmp(given, names[i]) == 0)
                return i;
    }
    // 'expected one of "static", "kinematic", "dynamic"', as scene files say it.
    int pieces = 0;
    for (int i = 0; names[i]; ++i) {
        lua_pushfstring(L, i == 0 ? "\"%s\"" : ", \"%s\"", names[i]);
        ++pieces;
    }
    lua_concat(L, pieces);
    if (lua_type(L, index) == LUA_TSTRING)
        raise(L, where, "%s%s: expected one of %s, got \"%s\"", prefix, name, lua_tostring(L, -1),
              lua_tostring(L, index));
    raise(L, where, "%s%s: expected one of %s, got %s", prefix, name, lua_tostring(L, -1),
          typeName(L, index));
}

} // namespace

float checkNumber(lua_State* L, int index, const char* where, const char* name) {
    return toFloat(L, index, where, "", name, false);
}

Vec2 checkVec2(lua_State* L, int index, const char* where, const char* xName, const char* yName) {
    const float x = toFloat(L, index, where, "", xName, false);
    return {x, toFloat(L, index + 1, where, "", yName, false)};
}

float optNumber(lua_State* L, int index, const char* where, const char* name, float fallback) {
    if (lua_isnoneornil(L, index))
        return fallback;
    return toFloat(L, index, where, "", name, false);
}

float checkNumberOrInfinity(lua_State* L, int index, const char* where, const char* name) {
    return toFloat(L, index, where, "", name, true);
}

std::int64_t checkWhole(lua_State* L, int index, const char* where, const char* name,
                        std::int64_t min, std::int64_t max) {
    return toWhole(L, index, where, "", name, min, max);
}

bool checkBoolean(lua_State* L, int index, const char* where, const char* name) {
    return toBoolean(L, index, where, "", name);
}

int checkOption(lua_State* L, int index, const char* where, const char* name,
                const char* const* names) {
    return toOption(L, index, where, "", name, names);
}

int checkTable(lua_State* L, int index, const char* where, const char* name) {
    if (lua_type(L, index) != LUA_TTABLE)
        raise(L, where, "%s: expected a table, got %s", name, typeName(L, index));
    return absIndex(L, index);
}

// --- Fields ----------------------------------------------------------------------------

Fields::Fields(lua_State* L, int table, const char* where, const char* prefix)
    : L_(L), table_(absIndex(L, table)), where_(where), prefix_(prefix) {}

void Fields::fail(const char* name, const char* problem) const {
    raise(L_, where_, "%s%s: %s", prefix_, name, problem);
}

void Fields::allowOnly(const char* const* names) const {
    // The table's own name in front of the message: "filter: " for the prefix "filter.".
    char table[96] = "";
    if (const std::size_t length = std::strlen(prefix_); length > 0)
        std::snprintf(table, sizeof table, "%.*s: ", static_cast<int>(length - 1), prefix_);
    luaL_checkstack(L_, 4, "jostle: allowOnly");
    lua_pushnil(L_);
    while (lua_next(L_, table_) != 0) {
        lua_pop(L_, 1); // the value
        if (lua_type(L_, -1) == LUA_TSTRING) {
            const char* key = lua_tostring(L_, -1);
            bool known = false;
            for (int i = 0; names[i] && !known; ++i)
                known = std::strcmp(key, names[i]) == 0;
            if (!known) {
                // ' (did you mean "snapDown"?)' for the known name it was probably meant to be.
                NearestName nearest(key);
                for (int i = 0; names[i]; ++i)
                    nearest.consider(names[i]);
                char note[96];
                didYouMean(nearest.name(), note, sizeof note);
                raise(L_, where_, "%sunknown field \"%s\"%s", table, key, note);
            }
        } else {
            // {0, 0, 10, 10}: positions are not names. Say what the key was without
            // converting it in place (that would confuse lua_next).
            char key[64];
            if (lua_type(L_, -1) == LUA_TNUMBER)
                std::snprintf(key, sizeof key, "[%.14g]",
                              static_cast<double>(lua_tonumber(L_, -1)));
            else
                std::snprintf(key, sizeof key, "of type %s", typeName(L_, -1));
            raise(L_, where_, "%sunknown field %s: fields are given by name, e.g. {x = 0}", table,
                  key);
        }
    }
}

void Fields::push(const char* name) const {
    lua_pushstring(L_, name);
    lua_rawget(L_, table_);
}

bool Fields::has(const char* name) const {
    push(name);
    const bool present = !lua_isnil(L_, -1);
    lua_pop(L_, 1);
    return present;
}

bool Fields::number(const char* name, float& out) const {
    push(name);
    const bool present = !lua_isnil(L_, -1);
    if (present)
        out = toFloat(L_, -1, where_, prefix_, name, false);
    lua_pop(L_, 1);
    return present;
}

bool Fields::numberOrInfinity(const char* name, float& out) const {
    push(name);
    const bool present = !lua_isnil(L_, -1);
    if (present)
        out = toFloat(L_, -1, where_, prefix_, name, true);
    lua_pop(L_, 1);
    return present;
}

bool Fields::whole(const char* name, int& out, int min, int max) const {
    push(name);
    const bool present = !lua_isnil(L_, -1);
    if (present)
        out = static_cast<int>(toWhole(L_, -1, where_, prefix_, name, min, max));
    lua_pop(L_, 1);
    return present;
}

bool Fields::bits(const char* name, std::uint32_t& out) const {
    push(name);
    const bool present = !lua_isnil(L_, -1);
    if (present)
        out = static_cast<std::uint32_t>(
            toWhole(L_, -1, where_, prefix_, name, 0, std::numeric_limits<std::uint32_t>::max()));
    lua_pop(L_, 1);
    return present;
}

bool Fields::boolean(const char* name, bool& out) const {
    push(name);
    const bool present = !lua_isnil(L_, -1);
    if (present)
        out = toBoolean(L_, -1, where_, prefix_, name);
    lua_pop(L_, 1);
    return present;
}

bool Fields::vec2(const char* name, Vec2& out) const {
    push(name);
    const bool present = !lua_isnil(L_, -1);
    if (present) {
        if (lua_type(L_, -1) != LUA_TTABLE || rawLength(L_, -1) != 2) {
            if (lua_type(L_, -1) == LUA_TTABLE)
                raise(L_, where_, "%s%s: expected an array of 2 numbers, {x, y}", prefix_, name);
            raise(L_, where_, "%s%s: expected an array of 2 numbers, got %s", prefix_, name,
                  typeName(L_, -1));
        }
        float xy[2];
        for (int i = 0; i < 2; ++i) {
            lua_rawgeti(L_, -1, i + 1);
            char element[96];
            std::snprintf(element, sizeof element, "%s[%d]", name, i + 1);
            xy[i] = toFloat(L_, -1, where_, prefix_, element, false);
            lua_pop(L_, 1);
        }
        out = {xy[0], xy[1]};
    }
    lua_pop(L_, 1);
    return present;
}

bool Fields::option(const char* name, int& out, const char* const* names) const {
    push(name);
    const bool present = !lua_isnil(L_, -1);
    if (present)
        out = toOption(L_, -1, where_, prefix_, name, names);
    lua_pop(L_, 1);
    return present;
}

} // namespace jostle::lua
