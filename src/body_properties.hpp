// Every property of a body, described once (properties.hpp has what a description is):
// its name, type, rule and default. The tables below bind each property to the
// definitions that have it (BodyDef, TileMapDef) and to their C structs. The checks
// (checkBodyDef, checkTileMapDef, World's setters), the scene loader, the C API's
// conversions and the Lua binding walk these tables instead of listing the properties
// again: a new property is one Property, one Field in each table, and its behaviour.
#pragma once

#include "jostle/tilemap.hpp"
#include "properties.hpp"

#include <cstdint>

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

} // namespace jostle::properties
