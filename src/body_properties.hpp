// Every property of a body, described once (properties.hpp has what a description is):
// its name, type, rule and default. The tables below bind each property to the
// definitions that have it (BodyDef, TileMapDef), to their C structs and, for a body, to
// where a world keeps it (body_state.hpp). The checks (checkBodyDef, checkTileMapDef),
// World's createBody, bodyDef, getters and setters, the scene loader, the C API's
// conversions and the Lua binding walk these tables instead of listing the properties
// again: a new property is one Property, one row in each table, and its behaviour.
#pragma once

#include "body_state.hpp"
#include "jostle/tilemap.hpp"
#include "properties.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <type_traits>
#include <variant>

namespace jostle::properties {

// --- Properties --------------------------------------------------------------------------

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

// --- Where a world keeps a body's property ----------------------------------------------

/// One number of a vector a Body keeps: BodyDef::x is Body::position's x.
struct VectorPart {
    Vec2 Body::*vector;
    float Vec2::*part;
};

/// Where a world keeps a property of a body: a member of its Body (what the steps read),
/// of its KeptAsGiven (what they do not read, as given: the steps read what is derived
/// from it, deriveFrom) or of its Shape, or one number of a vector of its Body.
template <class... T>
using StoreOf = std::variant<T Body::*..., T KeptAsGiven::*..., T Shape::*..., VectorPart>;

template <class S> struct StoredTypeOf;
template <class T, class Where> struct StoredTypeOf<T Where::*> { using type = T; };
template <> struct StoredTypeOf<VectorPart> { using type = float; };
/// The type of what a store alternative holds.
template <class S> using StoredType = typename StoredTypeOf<S>::type;

/// A body's property: its Field, and where a world keeps it.
template <class... T> struct BodyFieldOf : Field<BodyDef, jostle_body_def, T...> {
    template <class U, class S>
    constexpr BodyFieldOf(const Property& p, U BodyDef::*m, CType<U> jostle_body_def::*c, S s)
        : Field<BodyDef, jostle_body_def, T...>(p, m, c), store(s) {
        static_assert(std::is_same_v<U, StoredType<S>>, "a property is kept as another type");
    }

    /// Calls f(member, store) with the BodyDef member and the store of their own types.
    template <class F> void visitStore(F&& f) const {
        std::visit(
            [&](auto m, auto s) {
                using U = std::remove_cvref_t<decltype(std::declval<BodyDef&>().*m)>;
                if constexpr (std::is_same_v<U, StoredType<decltype(s)>>)
                    f(m, s);
            },
            this->member, store);
    }

    StoreOf<T...> store;
};

using BodyField = BodyFieldOf<BodyType, float, Vec2, bool, std::uint32_t, void*>;
using TileMapField = Field<TileMapDef, jostle_tile_map_def, float, Vec2, bool, std::uint32_t,
                           void*>; // a map has no type

constexpr VectorPart xOf(Vec2 Body::*vector) {
    return {vector, &Vec2::x};
}
constexpr VectorPart yOf(Vec2 Body::*vector) {
    return {vector, &Vec2::y};
}

// clang-format off
/// BodyDef's members, in body.hpp's order: the order in which checkBodyDef reports.
inline constexpr BodyField kBodyFields[] = {
    {kType, &BodyDef::type, &jostle_body_def::type, &Body::type},
    {kX, &BodyDef::x, &jostle_body_def::x, xOf(&Body::position)},
    {kY, &BodyDef::y, &jostle_body_def::y, yOf(&Body::position)},
    {kHw, &BodyDef::hw, &jostle_body_def::hw, xOf(&Body::half)},
    {kHh, &BodyDef::hh, &jostle_body_def::hh, yOf(&Body::half)},
    {kVx, &BodyDef::vx, &jostle_body_def::vx, xOf(&Body::velocity)},
    {kVy, &BodyDef::vy, &jostle_body_def::vy, yOf(&Body::velocity)},
    {kBounce, &BodyDef::bounce, &jostle_body_def::bounce, &Body::bounce},
    {kFriction, &BodyDef::friction, &jostle_body_def::friction, &Body::friction},
    {kMass, &BodyDef::mass, &jostle_body_def::mass, &Body::mass},
    {kDensity, &BodyDef::density, &jostle_body_def::density, &KeptAsGiven::density},
    {kGravityScale, &BodyDef::gravityScale, &jostle_body_def::gravity_scale, &Body::gravityScale},
    {kDamping, &BodyDef::damping, &jostle_body_def::damping, &Body::damping},
    {kBullet, &BodyDef::bullet, &jostle_body_def::bullet, &Body::bullet},
    {kOneWay, &BodyDef::oneWay, &jostle_body_def::one_way, &Body::oneWay},
    {kCategory, &BodyDef::category, &jostle_body_def::category, &Body::category},
    {kMask, &BodyDef::mask, &jostle_body_def::mask, &Body::mask},
    {kSensor, &BodyDef::sensor, &jostle_body_def::sensor, &Body::sensor},
    {kUserData, &BodyDef::userData, &jostle_body_def::user_data, &KeptAsGiven::userData},
    {kCharacter, &BodyDef::character, &jostle_body_def::character, &Body::character},
    {kWallFriction, &BodyDef::wallFriction, &jostle_body_def::wall_friction, &Body::wallFriction},
    {kFloorAngle, &BodyDef::floorAngle, &jostle_body_def::floor_angle, &KeptAsGiven::floorAngle},
    {kSnapDown, &BodyDef::snapDown, &jostle_body_def::snap_down, &Body::snapDown},
    {kCornerCorrection, &BodyDef::cornerCorrection, &jostle_body_def::corner_correction,
     &KeptAsGiven::cornerCorrection},
    {kStepUp, &BodyDef::stepUp, &jostle_body_def::step_up, &KeptAsGiven::stepUp},
    {kRadius, &BodyDef::radius, &jostle_body_def::radius, &Shape::radius},
    {kSlope, &BodyDef::slope, &jostle_body_def::slope, &Shape::slope},
    {kSegment, &BodyDef::segment, &jostle_body_def::segment, &Shape::segment},
    {kSurfaceVelocity, &BodyDef::surfaceVelocity, &jostle_body_def::surface_velocity,
     &Body::surfaceVelocity},
};
// clang-format on

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

/// For each row of kTileMapFields, the row of kBodyFields of the same property, which a
/// map's bodies take from the map (friction, oneWay, userData...), or nullptr: the tile,
/// and x and y, the map's corner (its bodies' centres are worked out from the tiles).
inline constexpr auto kMapToBodyFields = [] {
    std::array<const BodyField*, std::size(kTileMapFields)> rows{};
    for (std::size_t i = 0; i < rows.size(); ++i)
        if (kTileMapFields[i].property != &kX && kTileMapFields[i].property != &kY)
            rows[i] = find(kBodyFields, *kTileMapFields[i].property);
    return rows;
}();

/// Gives `body` each setting of `map` that a map's bodies take from it (kMapToBodyFields).
inline void shareWithBody(const TileMapDef& map, BodyDef& body) {
    for (std::size_t i = 0; i < std::size(kTileMapFields); ++i)
        if (const BodyField* row = kMapToBodyFields[i])
            std::visit(
                [&](auto from, auto to) {
                    using From = std::remove_cvref_t<decltype(map.*from)>;
                    if constexpr (std::is_same_v<From, std::remove_cvref_t<decltype(body.*to)>>)
                        body.*to = map.*from;
                },
                kTileMapFields[i].member, row->member);
}

// --- A body's properties where a world keeps them ----------------------------------------

/// The places of one body in a world: its Body, KeptAsGiven and Shape.
template <class B, class K, class S> struct PlacesOf {
    B& body;
    K& kept;
    S& shape;
};
using Places = PlacesOf<Body, KeptAsGiven, Shape>;
using ConstPlaces = PlacesOf<const Body, const KeptAsGiven, const Shape>;

/// The value a store names among a body's places.
template <class P, class T> auto& at(P places, T Body::*member) {
    return places.body.*member;
}
template <class P, class T> auto& at(P places, T KeptAsGiven::*member) {
    return places.kept.*member;
}
template <class P, class T> auto& at(P places, T Shape::*member) {
    return places.shape.*member;
}
template <class P> auto& at(P places, VectorPart part) {
    return (places.body.*part.vector).*part.part;
}

/// Keeps each property of `def` where the world keeps it.
inline void keep(const BodyDef& def, Places places) {
    for (const BodyField& field : kBodyFields)
        field.visitStore([&](auto member, auto store) { at(places, store) = def.*member; });
}

/// The definition of a body, from where the world keeps its properties.
inline BodyDef definitionOf(ConstPlaces places) {
    BodyDef def;
    for (const BodyField& field : kBodyFields)
        field.visitStore([&](auto member, auto store) { def.*member = at(places, store); });
    return def;
}

} // namespace jostle::properties
