// Scene files: the fields of a world's, a body's and a tile map's definition, read by their
// descriptions (world_options.hpp, body_properties.hpp), for the scene reader
// (scene_reader.cpp).
#pragma once

#include "body_properties.hpp"
#include "json.hpp"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>

namespace jostle::scene_file {

using namespace json;

inline BodyType readBodyType(const Json& value, const std::string& place) {
    if (auto type = bodyTypeFromString(readString(value, place)))
        return *type;
    fail(place, R"(expected one of "static", "kinematic", "dynamic")");
}

// --- Definitions: fields by their descriptions (properties.hpp) ------------------------

// A value of each type a property has; a pointer (userData) has no form in a file.
inline void readValue(const Json& value, const std::string& place, BodyType& out) {
    out = readBodyType(value, place);
}
inline void readValue(const Json& value, const std::string& place, float& out) {
    out = readFloat(value, place);
}
inline void readValue(const Json& value, const std::string& place, Vec2& out) {
    out = readVec2(value, place);
}
inline void readValue(const Json& value, const std::string& place, bool& out) {
    out = readBool(value, place);
}
inline void readValue(const Json& value, const std::string& place, std::uint32_t& out) {
    out = readBits(value, place);
}
inline void readValue(const Json& value, const std::string& place, int& out) {
    out = readInt(value, place);
}
inline void readValue(const Json& value, const std::string& place, Solver& out) {
    auto solver = solverFromString(readString(value, place));
    if (!solver)
        fail(place, R"(expected "classic" or "physical")");
    out = *solver;
}
inline void readValue(const Json& value, const std::string& place, FrictionMix& out) {
    auto mix = frictionMixFromString(readString(value, place));
    if (!mix)
        fail(place, R"(expected "min" or "geometricMean")");
    out = *mix;
}

template <class T, class Def, class U> constexpr bool isMemberOf(U Def::*) {
    return std::is_same_v<T, U>;
}

/// True if a file can give the field: all but a pointer (userData).
template <class F> inline bool inFile(const F& field) {
    return std::visit([](auto member) { return !isMemberOf<void*>(member); }, field.member);
}

/// True if the field's value is a whole number (velocityIterations).
template <class F> inline bool isWhole(const F& field) {
    return std::visit([](auto member) { return isMemberOf<int>(member); }, field.member);
}

/// True if the field's value is an array of 2 numbers (oneWay, slope).
template <class F> inline bool isVec2(const F& field) {
    return std::visit([](auto member) { return isMemberOf<Vec2>(member); }, field.member);
}

/// Reads `field` of `def` from `value`; the field is one a file can give.
template <class Def, class F>
void readField(Def& def, const F& field, const Json& value, const std::string& place) {
    std::visit(
        [&](auto member) {
            if constexpr (requires { readValue(value, place, def.*member); })
                readValue(value, place, def.*member);
        },
        field.member);
}

// The same values written as a file holds them.
inline Json fileValue(BodyType type) {
    return toString(type);
}
inline Json fileValue(Vec2 v) {
    return Json::array({v.x, v.y});
}
inline Json fileValue(Solver solver) {
    return toString(solver);
}
inline Json fileValue(FrictionMix mix) {
    return toString(mix);
}
template <class T>
requires std::is_arithmetic_v<T>
inline Json fileValue(T value) {
    return value;
}

/// Writes each field of `def` that a file can give, by its name, as a file holds it.
template <class Def, class F, std::size_t N> Json fileFields(const Def& def, const F (&fields)[N]) {
    Json out = Json::object();
    for (const F& field : fields)
        std::visit(
            [&](auto member) {
                if constexpr (requires { fileValue(def.*member); })
                    out[field.property->name] = fileValue(def.*member);
            },
            field.member);
    return out;
}

constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

/// The index in `fields` of the field a file calls `name`, or kNone.
template <class F, std::size_t N>
std::size_t fileFieldIndex(const F (&fields)[N], std::string_view name) {
    const F* field = properties::find(fields, name);
    return field && inFile(*field) ? static_cast<std::size_t>(field - fields) : kNone;
}

/// The index of `name` in `names`, or kNone.
template <std::size_t N>
std::size_t indexOf(const std::string_view (&names)[N], std::string_view name) {
    for (std::size_t i = 0; i < N; ++i)
        if (names[i] == name)
            return i;
    return kNone;
}

} // namespace jostle::scene_file
