// Every property of a body, described once: its name, its type (its default's), the rule
// its values follow and its default. The tables below bind each property to the
// definitions that have it (BodyDef, TileMapDef) and to their C structs. The checks
// (checkBodyDef, checkTileMapDef, World's setters), the scene loader, the C API's
// conversions and the Lua binding walk these tables instead of listing the properties
// again: a new property is one Property, one Field in each table, and its behaviour.
#pragma once

#include "jostle/body.hpp"
#include "jostle/jostle.h"
#include "jostle/tilemap.hpp"
#include "range_check.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>

namespace jostle::properties {

// --- Rules -------------------------------------------------------------------------------

/// What values a property takes: a few checks made in order (stepsOf), each giving the
/// problem in the words errors use ("must be > 0"), or nullptr.
enum class Rule : std::uint8_t {
    Any,         ///< every value of its type: bits, flags, user data, a type jostle names
    Finite,      ///< a number in range (math.hpp)
    Size,        ///< in range, > 0 and >= 1e-9: half extents, density
    Unit,        ///< in [0, 1]
    NonNegative, ///< in range and >= 0
    MassOrZero,  ///< in range, >= 0, and 0 (the mass comes from density) or >= 1e-9
    Direction,   ///< a vector: {0, 0} or a unit vector along x or y (oneWay)
    Corner,      ///< a vector: {0, 0} or each component -1 or +1 (slope)
    FloorAngle,  ///< degrees in [0, 90)
};

namespace checks {
inline const char* inRange(float v) {
    return rangeProblem(v);
}
inline const char* positive(float v) {
    return v > 0.0f ? nullptr : "must be > 0";
}
inline const char* notTiny(float v) {
    return v >= kMinMagnitude ? nullptr : "must be >= 1e-9";
}
inline const char* unit(float v) {
    return v >= 0.0f && v <= 1.0f ? nullptr : "must be in [0, 1]";
}
inline const char* nonNegative(float v) {
    return v >= 0.0f ? nullptr : "must be >= 0";
}
inline const char* massNonNegative(float v) {
    return v >= 0.0f ? nullptr : "must be >= 0 (0: from density)";
}
inline const char* floorAngle(float v) {
    return v >= 0.0f && v < 90.0f ? nullptr : "must be in [0, 90)";
}
inline const char* massZeroOrNotTiny(float v) {
    return v == 0.0f || v >= kMinMagnitude ? nullptr : "must be 0 (from density) or >= 1e-9";
}
} // namespace checks

using NumberCheck = const char* (*)(float);
inline constexpr std::size_t kMaxSteps = 3;

/// The checks of a rule on numbers, in order; none for the other rules.
constexpr std::array<NumberCheck, kMaxSteps> stepsOf(Rule rule) {
    using namespace checks;
    switch (rule) {
    case Rule::Finite:
        return {inRange};
    case Rule::Size:
        return {inRange, positive, notTiny};
    case Rule::Unit:
        return {unit}; // which no NaN passes: a setter's NaN is "not in [0, 1]"
    case Rule::NonNegative:
        return {inRange, nonNegative};
    case Rule::MassOrZero:
        return {inRange, massNonNegative, massZeroOrNotTiny};
    case Rule::FloorAngle:
        return {floorAngle}; // which no NaN passes
    case Rule::Any:
    case Rule::Direction:
    case Rule::Corner:
        break;
    }
    return {};
}

/// Check number `step` of `rule` on one value: its problem, or nullptr if it passes or the
/// rule has no such check.
inline const char* stepProblem(Rule rule, std::size_t step, float value) {
    const NumberCheck check = stepsOf(rule)[step];
    return check ? check(value) : nullptr;
}
inline const char* stepProblem(Rule rule, std::size_t step, Vec2 value) {
    if (rule == Rule::Direction && step == 0 && !isValidOneWay(value))
        return "must be {0, 0} or one of {1, 0}, {-1, 0}, {0, 1}, {0, -1}";
    if (rule == Rule::Corner && step == 0 && !isValidSlope(value))
        return "must be {0, 0} or each component -1 or 1";
    return nullptr;
}
template <class T> const char* stepProblem(Rule, std::size_t, T) {
    return nullptr; // Rule::Any
}

/// The problem with one value under `rule`, all its checks in order (a setter's argument).
template <class T> const char* problemOf(Rule rule, T value) {
    for (std::size_t step = 0; step < kMaxSteps; ++step)
        if (const char* problem = stepProblem(rule, step, value))
            return problem;
    return nullptr;
}

/// Whether a value is one jostle can hold at all, whatever its property: a number in
/// range (each of a vector's on its own), a type jostle names. A definition is checked for
/// this first, so that no rule ever sees a NaN.
inline const char* formProblem(float value) {
    return rangeProblem(value);
}
inline const char* formProblem(Vec2 value) {
    const char* problem = rangeProblem(value.x);
    return problem ? problem : rangeProblem(value.y);
}
inline const char* formProblem(BodyType type) {
    const bool named =
        type == BodyType::Static || type == BodyType::Kinematic || type == BodyType::Dynamic;
    return named ? nullptr : "must be static, kinematic or dynamic";
}
template <class T> const char* formProblem(T) {
    return nullptr;
}

// --- Properties --------------------------------------------------------------------------

/// A value of any property's type.
using Value = std::variant<BodyType, float, Vec2, bool, std::uint32_t, void*>;

/// One property, as every definition that has it describes it.
struct Property {
    const char* name; ///< the member's name, which is also the scene file's and Lua's field
    Rule rule;
    Value byDefault;
    /// Scene files and Lua tables must give it: no default makes sense (a box's size).
    bool required = false;
};

// The members of body.hpp. x and y are a position: a body's centre, a tile map's corner.
inline constexpr Property kType{"type", Rule::Any, BodyType::Dynamic};
inline constexpr Property kX{"x", Rule::Finite, 0.0f};
inline constexpr Property kY{"y", Rule::Finite, 0.0f};
inline constexpr Property kHw{"hw", Rule::Size, 0.0f, true};
inline constexpr Property kHh{"hh", Rule::Size, 0.0f, true};
inline constexpr Property kVx{"vx", Rule::Finite, 0.0f};
inline constexpr Property kVy{"vy", Rule::Finite, 0.0f};
inline constexpr Property kBounce{"bounce", Rule::Unit, 0.0f};
inline constexpr Property kFriction{"friction", Rule::Unit, 0.5f};
inline constexpr Property kMass{"mass", Rule::MassOrZero, 0.0f};
inline constexpr Property kDensity{"density", Rule::Size, 1.0f};
inline constexpr Property kGravityScale{"gravityScale", Rule::Finite, 1.0f};
inline constexpr Property kDamping{"damping", Rule::NonNegative, 0.0f};
inline constexpr Property kBullet{"bullet", Rule::Any, false};
inline constexpr Property kOneWay{"oneWay", Rule::Direction, Vec2{}};
inline constexpr Property kCategory{"category", Rule::Any, std::uint32_t{1}};
inline constexpr Property kMask{"mask", Rule::Any, std::uint32_t{0xFFFFFFFF}};
inline constexpr Property kSensor{"sensor", Rule::Any, false};
inline constexpr Property kUserData{"userData", Rule::Any, static_cast<void*>(nullptr)};
inline constexpr Property kCharacter{"character", Rule::Any, false};
inline constexpr Property kWallFriction{"wallFriction", Rule::Unit, 0.0f};
inline constexpr Property kFloorAngle{"floorAngle", Rule::FloorAngle, 60.0f};
inline constexpr Property kSnapDown{"snapDown", Rule::NonNegative, 0.0f};
inline constexpr Property kCornerCorrection{"cornerCorrection", Rule::NonNegative, 0.0f};
inline constexpr Property kStepUp{"stepUp", Rule::NonNegative, 0.0f};
inline constexpr Property kRadius{"radius", Rule::NonNegative, 0.0f};
inline constexpr Property kSlope{"slope", Rule::Corner, Vec2{}};
inline constexpr Property kSegment{"segment", Rule::Any, false};
inline constexpr Property kSurfaceVelocity{"surfaceVelocity", Rule::Any, Vec2{}};
/// A tile map's own: the side of its square tiles (checkTileMapDef has its further rules).
inline constexpr Property kTile{"tile", Rule::Finite, 0.0f, true};

/// The C API's type for a property's type.
template <class T> struct CTypeOf { using type = T; };
template <> struct CTypeOf<BodyType> { using type = jostle_body_type; };
template <> struct CTypeOf<Vec2> { using type = jostle_vec2; };
template <class T> using CType = typename CTypeOf<T>::type;

/// True if `rule` is one for values of type T.
template <class T> constexpr bool ruleFits(Rule rule) {
    if constexpr (std::is_same_v<T, float>)
        return rule != Rule::Direction && rule != Rule::Corner;
    else if constexpr (std::is_same_v<T, Vec2>)
        return rule == Rule::Direction || rule == Rule::Corner || rule == Rule::Any;
    else
        return rule == Rule::Any;
}

/// A property as a member of the definition Def and of its C struct CDef (whose member is
/// the property's C name: gravity_scale, one_way, user_data). T... are the types of the
/// definition's properties.
template <class Def, class CDef, class... T> struct Field {
    template <class U>
    constexpr Field(const Property& p, U Def::*m, CType<U> CDef::*c)
        : property(&p), member(m), cMember(c) {
        // In a constexpr table, a property bound to a member of another type does not compile.
        if (!std::holds_alternative<U>(p.byDefault) || !ruleFits<U>(p.rule))
            throw "a property's type, rule and member disagree";
    }

    /// Calls f(member, cMember) with both member pointers of their own types.
    template <class F> void visitWithC(F&& f) const {
        std::visit(
            [&](auto m) {
                using U = std::remove_cvref_t<decltype(std::declval<Def&>().*m)>;
                f(m, std::get<CType<U> CDef::*>(cMember));
            },
            member);
    }

    const Property* property;
    std::variant<T Def::*...> member;
    std::variant<CType<T> CDef::*...> cMember;
};

using BodyField =
    Field<BodyDef, jostle_body_def, BodyType, float, Vec2, bool, std::uint32_t, void*>;
using TileMapField = Field<TileMapDef, jostle_tile_map_def, float, Vec2, bool, std::uint32_t,
                           void*>; // a map has no type

/// BodyDef's members, in body.hpp's order: the order in which checkBodyDef reports.
inline constexpr BodyField kBodyFields[] = {
    {kType, &BodyDef::type, &jostle_body_def::type},
    {kX, &BodyDef::x, &jostle_body_def::x},
    {kY, &BodyDef::y, &jostle_body_def::y},
    {kHw, &BodyDef::hw, &jostle_body_def::hw},
    {kHh, &BodyDef::hh, &jostle_body_def::hh},
    {kVx, &BodyDef::vx, &jostle_body_def::vx},
    {kVy, &BodyDef::vy, &jostle_body_def::vy},
    {kBounce, &BodyDef::bounce, &jostle_body_def::bounce},
    {kFriction, &BodyDef::friction, &jostle_body_def::friction},
    {kMass, &BodyDef::mass, &jostle_body_def::mass},
    {kDensity, &BodyDef::density, &jostle_body_def::density},
    {kGravityScale, &BodyDef::gravityScale, &jostle_body_def::gravity_scale},
    {kDamping, &BodyDef::damping, &jostle_body_def::damping},
    {kBullet, &BodyDef::bullet, &jostle_body_def::bullet},
    {kOneWay, &BodyDef::oneWay, &jostle_body_def::one_way},
    {kCategory, &BodyDef::category, &jostle_body_def::category},
    {kMask, &BodyDef::mask, &jostle_body_def::mask},
    {kSensor, &BodyDef::sensor, &jostle_body_def::sensor},
    {kUserData, &BodyDef::userData, &jostle_body_def::user_data},
    {kCharacter, &BodyDef::character, &jostle_body_def::character},
    {kWallFriction, &BodyDef::wallFriction, &jostle_body_def::wall_friction},
    {kFloorAngle, &BodyDef::floorAngle, &jostle_body_def::floor_angle},
    {kSnapDown, &BodyDef::snapDown, &jostle_body_def::snap_down},
    {kCornerCorrection, &BodyDef::cornerCorrection, &jostle_body_def::corner_correction},
    {kStepUp, &BodyDef::stepUp, &jostle_body_def::step_up},
    {kRadius, &BodyDef::radius, &jostle_body_def::radius},
    {kSlope, &BodyDef::slope, &jostle_body_def::slope},
    {kSegment, &BodyDef::segment, &jostle_body_def::segment},
    {kSurfaceVelocity, &BodyDef::surfaceVelocity, &jostle_body_def::surface_velocity},
};

/// TileMapDef's members but its rows, which are a map's alone, in tilemap.hpp's order.
inline constexpr TileMapField kTileMapFields[] = {
    {kX, &TileMapDef::x, &jostle_tile_map_def::x},
    {kY, &TileMapDef::y, &jostle_tile_map_def::y},
    {kTile, &TileMapDef::tile, &jostle_tile_map_def::tile},
    {kFriction, &TileMapDef::friction, &jostle_tile_map_def::friction},
    {kBounce, &TileMapDef::bounce, &jostle_tile_map_def::bounce},
    {kCategory, &TileMapDef::category, &jostle_tile_map_def::category},
    {kMask, &TileMapDef::mask, &jostle_tile_map_def::mask},
    {kOneWay, &TileMapDef::oneWay, &jostle_tile_map_def::one_way},
    {kSensor, &TileMapDef::sensor, &jostle_tile_map_def::sensor},
    {kUserData, &TileMapDef::userData, &jostle_tile_map_def::user_data},
};

// --- Walking a table ---------------------------------------------------------------------

/// The field named `name`, or nullptr.
template <class F, std::size_t N>
constexpr const F* find(const F (&fields)[N], std::string_view name) {
    for (const F& field : fields)
        if (name == field.property->name)
            return &field;
    return nullptr;
}

/// The first value of `def` not of a form jostle can hold (formProblem), in table order.
template <class Def, class F, std::size_t N>
std::optional<FieldError> formProblem(const Def& def, const F (&fields)[N]) {
    for (const F& field : fields) {
        auto check = [&](auto member) { return formProblem(def.*member); };
        if (const char* problem = std::visit(check, field.member))
            return FieldError{field.property->name, problem};
    }
    return std::nullopt;
}

/// The first value of `def` that its rule refuses, in table order. Fields side by side
/// under one rule (hw, hh) take each check in turn: both > 0 before either's minimum.
template <class Def, class F, std::size_t N>
std::optional<FieldError> ruleProblem(const Def& def, const F (&fields)[N]) {
    for (std::size_t begin = 0, end = 0; begin < N; begin = end) {
        const Rule rule = fields[begin].property->rule;
        for (end = begin + 1; end < N && fields[end].property->rule == rule; ++end) {
        }
        for (std::size_t step = 0; step < kMaxSteps; ++step)
            for (std::size_t i = begin; i < end; ++i) {
                auto check = [&](auto member) { return stepProblem(rule, step, def.*member); };
                if (const char* problem = std::visit(check, fields[i].member))
                    return FieldError{fields[i].property->name, problem};
            }
    }
    return std::nullopt;
}

/// True if every field of `defaults` (a default-made Def) holds its property's default.
template <class Def, class F, std::size_t N>
constexpr bool defaultsAgree(const Def& defaults, const F (&fields)[N]) {
    for (const F& field : fields) {
        auto agrees = [&](auto member) {
            using T = std::remove_cvref_t<decltype(defaults.*member)>;
            return defaults.*member == std::get<T>(field.property->byDefault);
        };
        if (!std::visit(agrees, field.member))
            return false;
    }
    return true;
}

} // namespace jostle::properties
