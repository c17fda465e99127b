// Argument checking and error raising for the Lua module.
//
// Two rules make errors safe in both interpreters:
// - Lua 5.4 raises errors with longjmp, which skips C++ destructors. So a Lua error is
//   raised only from frames that hold no C++ object with a destructor: C++ work runs
//   inside attempt() (or guard()), which catches every exception, copies the message
//   into a fixed buffer and returns; the Lua error is raised after that scope has ended.
// - LuaJIT raises errors as C++-compatible exceptions, which a catch (...) would catch.
//   So no Lua function that can raise is called inside attempt().
//
// Messages read "<where>: <what>: <problem>", e.g. "World:newBody: hw: must be > 0",
// with the same field names and wording as scene files (docs/scene-format.md).
#pragma once

#include "lua_compat.hpp"

#include <jostle/body.hpp>
#include <jostle/error.hpp>
#include <jostle/math.hpp>

#include <cstdint>
#include <cstdlib>
#include <exception>
#include <new>

namespace jostle::lua {

inline constexpr std::size_t kMessageSize = 512;

/// Raises a Lua error "<where>: <formatted>", with the caller's position in front as
/// luaL_error does. The format is lua_pushfstring's (%s, %d, %f, %c, %%).
[[noreturn]] void raise(lua_State* L, const char* where, const char* format, ...);

/// Copies a C++ exception's message into `out`. jostle::Error's messages start with the
/// C++ function's name ("setMass: mass must be > 0"); that name is dropped, as the Lua
/// error puts the Lua method's name there instead, and the rest is written in Lua's
/// notation (src/notation.hpp: "character = true", not "BodyDef::character = true").
void describe(char (&out)[kMessageSize], const std::exception& error, bool fromJostle);
void copyMessage(char (&out)[kMessageSize], const char* text);
/// Describes the exception being handled: a jostle::Error or another std::exception as
/// describe() does, "out of memory", or "unexpected C++ exception". Called from a
/// catch-all, out of line: one handler in each function, not one per kind of exception.
void describeCurrentException(char (&out)[kMessageSize]) noexcept;
/// Copies a definition's problem (checkBodyDef, ...) as "field: problem", in Lua's notation.
void describe(char (&out)[kMessageSize], const FieldError& problem);

/// Runs `work`, catching every exception. False, with the message in `message`, if it
/// threw. `work` must not call Lua functions that can raise (see above).
template <class Work> bool attempt(char (&message)[kMessageSize], Work&& work) noexcept {
    try {
        work();
        return true;
    } catch (...) {
        describeCurrentException(message);
    }
    return false;
}

/// attempt(), then a Lua error "<where>: <message>" if `work` threw. Call it from a
/// frame that holds no C++ object with a destructor.
template <class Work> void guard(lua_State* L, const char* where, Work&& work) {
    char message[kMessageSize];
    if (!attempt(message, work))
        raise(L, where, "%s", message);
}

/// The type of a value for messages: Lua's type name, or "World", "Body", "TileMap",
/// "FixedStep" for the module's own userdata.
const char* typeName(lua_State* L, int index);

// --- Positional arguments ------------------------------------------------------------
//
// `name` is the argument's name in messages: "World:setGravity: x: expected a number,
// got string".

/// A number that is finite as a float.
float checkNumber(lua_State* L, int index, const char* where, const char* name);
/// Two numbers at `index` and `index + 1`, named `xName` and `yName`.
Vec2 checkVec2(lua_State* L, int index, const char* where, const char* xName, const char* yName);
/// checkNumber, or `fallback` for nil or none.
float optNumber(lua_State* L, int index, const char* where, const char* name, float fallback);
/// A number that is finite as a float or +infinity (math.huge): maxVelocity.
float checkNumberOrInfinity(lua_State* L, int index, const char* where, const char* name);
/// A whole number in [min, max].
std::int64_t checkWhole(lua_State* L, int index, const char* where, const char* name,
                        std::int64_t min, std::int64_t max);
bool checkBoolean(lua_State* L, int index, const char* where, const char* name);
/// The index of one of `names` (a list ended by nullptr) equal to the string argument.
int checkOption(lua_State* L, int index, const char* where, const char* name,
                const char* const* names);
/// A table (raises otherwise); returns its absolute index.
int checkTable(lua_State* L, int index, const char* where, const char* name);

// --- Definition tables ---------------------------------------------------------------
//
// The fields of {type = "dynamic", x = 0, hw = 10, ...}. Fields are read raw (no
// metamethods), like the check for unknown fields, so what is checked is what is used.

class Fields {
public:
    /// `prefix` goes before field names in messages: "filter." gives "filter.mask".
    Fields(lua_State* L, int table, const char* where, const char* prefix = "");

    /// Raises on a key that is not one of `names` (a list ended by nullptr): a typo
    /// must not pass silently. The message names the known field it was probably meant to
    /// be, as scene files do (src/suggest.hpp).
    void allowOnly(const char* const* names) const;

    bool has(const char* name) const;
    /// Each reads the field into `out` if it is present (and returns true), leaves `out`
    /// alone if it is nil, and raises if it has the wrong type or value.
    bool number(const char* name, float& out) const;
    bool numberOrInfinity(const char* name, float& out) const;
    bool whole(const char* name, int& out, int min, int max) const;
    bool bits(const char* name, std::uint32_t& out) const;
    bool boolean(const char* name, bool& out) const;
    /// An array of two numbers, {x, y}.
    bool vec2(const char* name, Vec2& out) const;
    /// A string, one of `names` (ended by nullptr): its index.
    bool option(const char* name, int& out, const char* const* names) const;
    /// Pushes the raw field (nil if absent).
    void push(const char* name) const;

    [[noreturn]] void fail(const char* name, const char* problem) const;

private:
    lua_State* L_;
    int table_;
    const char* where_;
    const char* prefix_;
};

} // namespace jostle::lua
