// Floors, walls and ceilings: what a surface that pushes a body is to it, relative to
// gravity (floorAngle says how steep a floor may be), and what a body stands on. Touching
// flags, events, characters, snapping and corners all ask here (docs/events.md,
// docs/characters.md).
#pragma once

#include "handles.hpp"
#include "jostle/body.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace jostle {

struct WorldState;

/// Touching bits, by slot.
enum TouchingBit : std::uint8_t {
    kFloor = 1,
    kCeiling = 2,
    kWallLeft = 4,
    kWallRight = 8,
};

/// Where gravity pulls, as a unit vector; with no gravity, the screen's down (y grows
/// downward). A gravity too weak for its length to be a float (1e-39) is scaled up first.
inline Vec2 downOf(Vec2 gravity) {
    if (gravity == Vec2{})
        return {0.0f, 1.0f};
    const float inverse = 1.0f / length(gravity);
    if (std::isfinite(inverse))
        return gravity * inverse;
    const float largest = std::max(std::abs(gravity.x), std::abs(gravity.y));
    const Vec2 scaled{gravity.x / largest, gravity.y / largest};
    return scaled * (1.0f / length(scaled));
}

/// What a surface that pushes a body along `push` is to it, with gravity along `down`
/// (both unit): a floor pushes against gravity, at least `floorCos` of it (Body::floorCos:
/// within its floor angle of straight up), a ceiling with it (within 60 degrees), a wall
/// sideways.
inline TouchingBit surfaceOf(Vec2 push, Vec2 down, float floorCos) {
    const float vertical = dot(push, down);
    if (-vertical >= floorCos)
        return kFloor;
    if (vertical > 0.5f)
        return kCeiling;
    return dot(push, Vec2{down.y, -down.x}) < 0.0f ? kWallRight : kWallLeft;
}

/// What body `id` stands on: of the bodies it touched at the end of the last step that
/// pushed it as a floor, the one that pushed hardest (the first of equals). Null if none
/// (World::ground).
struct GroundRecord {
    BodyId body;
    Vec2 normal;
};
GroundRecord groundOf(const WorldState& world, BodyId id);

} // namespace jostle
