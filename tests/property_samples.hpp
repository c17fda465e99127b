// For tests that walk the tables of src/body_properties.hpp and src/world_options.hpp: a
// valid value of each property that is not its default, what else a body needs to take
// it, reading and writing a field by its table entry, and every table by name.
#pragma once

#include "body_properties.hpp"
#include "notation.hpp"
#include "world_options.hpp"

#include <cstdio>
#include <initializer_list>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace jostle::test_support {

/// The first of `candidates` that is not `byDefault`.
template <class T> T otherThan(T byDefault, std::initializer_list<T> candidates) {
    for (const T& candidate : candidates)
        if (!(candidate == byDefault))
            return candidate;
    return byDefault; // not reached: each list has two values
}

/// A value of `property` that its definition (BodyDef, TileMapDef, WorldDef and its
/// options) accepts and that is not its default (Properties.EverySampleIsNotItsDefault),
/// so that a row given back as its default fails the tests that walk the tables.
inline properties::Value sampleOf(const properties::Property& property) {
    using properties::Rule;
    static int anchor; // something for userData to point to
    const properties::Interval& range = property.range;
    auto sample = [&](auto byDefault) -> properties::Value {
        using T = decltype(byDefault);
        if constexpr (std::is_same_v<T, int>) {
            return range.contains(byDefault + 1) ? byDefault + 1 : byDefault - 1;
        } else if constexpr (std::is_same_v<T, float>) {
            const auto middle = static_cast<float>((range.low + range.high) / 2);
            switch (property.rule) {
            case Rule::Interval:
                return otherThan(byDefault, {middle, (static_cast<float>(range.low) + middle) / 2});
            case Rule::Unit:
                return otherThan(byDefault, {0.25f, 0.75f});
            case Rule::Size:
                return otherThan(byDefault, {2.5f, 1.5f});
            case Rule::MassOrZero:
                return otherThan(byDefault, {3.0f, 2.0f});
            case Rule::NonNegative:
                return otherThan(byDefault, {0.75f, 0.5f});
            default:
                return otherThan(byDefault, {7.5f, 2.5f});
            }
        } else if constexpr (std::is_same_v<T, Vec2>) {
            return property.rule == Rule::Corner
                       ? otherThan(byDefault, {{1.0f, -1.0f}, {-1.0f, 1.0f}})
                       : otherThan(byDefault, {{0.0f, -1.0f}, {1.0f, 0.0f}});
        } else if constexpr (std::is_same_v<T, bool>) {
            return !byDefault;
        } else if constexpr (std::is_same_v<T, std::uint32_t>) {
            return byDefault ^ 6u;
        } else if constexpr (std::is_same_v<T, BodyType>) {
            return otherThan(byDefault, {BodyType::Kinematic, BodyType::Static});
        } else if constexpr (std::is_same_v<T, Solver>) {
            return otherThan(byDefault, {Solver::Classic, Solver::Physical});
        } else if constexpr (std::is_same_v<T, FrictionMix>) {
            return otherThan(byDefault, {FrictionMix::GeometricMean, FrictionMix::Min});
        } else {
            return static_cast<void*>(&anchor);
        }
    };
    return std::visit(sample, property.byDefault);
}

/// A property and a value of it.
using Setting = std::pair<const properties::Property*, properties::Value>;

/// What a body must also hold, besides the defaults and a size of 1 × 1 half extents, for
/// checkBodyDef to accept the sample of `property`: a ramp (slope) and a conveyor
/// (surfaceVelocity) are static or kinematic, and a segment is a ramp's face, so it needs a
/// slope too. Each value is a sample itself
/// (kinematic is the type's), so that a test writes them as it writes samples. The radius
/// sample (0.75) fits in half extents of 1 with nothing else.
inline std::vector<Setting> sampleNeeds(const properties::Property& property) {
    using namespace properties;
    if (&property == &kSlope || &property == &kSurfaceVelocity)
        return {{&kType, sampleOf(kType)}};
    if (&property == &kSegment)
        return {{&kType, sampleOf(kType)}, {&kSlope, sampleOf(kSlope)}};
    return {};
}

/// The value of `field` in `def`.
template <class Def, class F> properties::Value valueOf(const Def& def, const F& field) {
    return std::visit([&](auto member) -> properties::Value { return def.*member; }, field.member);
}

/// Sets `field` of `def` to `value` (of the field's type).
template <class Def, class F>
void setValue(Def& def, const F& field, const properties::Value& value) {
    std::visit(
        [&](auto member) {
            using T = std::remove_cvref_t<decltype(def.*member)>;
            def.*member = std::get<T>(value);
        },
        field.member);
}

/// `value` as a scene file (Notation::Json) or Lua writes it: [0, -1] or {0, -1}, "kinematic";
/// null (nil) for a pointer, which neither can hold.
inline std::string literalOf(const properties::Value& value, Notation notation) {
    const bool lua = notation == Notation::Lua;
    auto literal = [&](auto v) -> std::string {
        using T = decltype(v);
        char text[64];
        if constexpr (std::is_same_v<T, float>) {
            std::snprintf(text, sizeof text, "%.9g", static_cast<double>(v));
            return text;
        } else if constexpr (std::is_same_v<T, Vec2>) {
            std::snprintf(text, sizeof text, lua ? "{%.9g, %.9g}" : "[%.9g, %.9g]",
                          static_cast<double>(v.x), static_cast<double>(v.y));
            return text;
        } else if constexpr (std::is_same_v<T, bool>) {
            return v ? "true" : "false";
        } else if constexpr (std::is_same_v<T, std::uint32_t> || std::is_same_v<T, int>) {
            return std::to_string(v);
        } else if constexpr (std::is_same_v<T, void*>) {
            return lua ? "nil" : "null";
        } else {
            return std::string("\"") + toString(v) + "\""; // a name: BodyType, Solver, ...
        }
    };
    return std::visit(literal, value);
}

/// The part of a WorldDef that a table of world_options.hpp describes: the WorldDef itself,
/// its task system or one of its options.
inline WorldDef& partOf(WorldDef& def, const properties::WorldField&) {
    return def;
}
inline TaskSystem& partOf(WorldDef& def, const properties::TaskField&) {
    return def.tasks;
}
inline ClassicOptions& partOf(WorldDef& def, const properties::ClassicField&) {
    return def.classic;
}
inline PhysicalOptions& partOf(WorldDef& def, const properties::PhysicalField&) {
    return def.physical;
}

/// Calls f(name, table) for every table of a world's settings: its own fields, its task
/// system's and its options'; the name is the table's part of a WorldDef ("physical").
template <class F> void forEachWorldTable(F&& f) {
    f("world", properties::kWorldFields);
    f("tasks", properties::kTaskFields);
    f("classic", properties::kClassicFields);
    f("physical", properties::kPhysicalFields);
}

/// Calls f(name, table) for every table of settings: a world's, a body's and a tile map's.
/// A new table belongs here (or in forEachWorldTable), so that the tests that walk every
/// row of every table (test_properties.cpp, test_scene.cpp, and through jostle-test-rows
/// the Lua and JavaScript ones) walk it too.
template <class F> void forEachTable(F&& f) {
    forEachWorldTable(f);
    f("body", properties::kBodyFields);
    f("tileMap", properties::kTileMapFields);
}

} // namespace jostle::test_support
