// jostle/math.hpp: the one vector type of the API.
//
// jostle works in floats and in the user's units (pixels are fine). Nothing here
// is clever: a 2D vector and the few operations the library and its users need.
#pragma once

#include "jostle/visibility.h"
#include <cmath>

namespace jostle {
JOSTLE_EXPORT_BEGIN

/// A 2D vector: a position, a velocity, half extents or a normal.
struct Vec2 {
    float x = 0.0f;
    float y = 0.0f;

    /// The component along an axis: 0 is x, 1 is y.
    constexpr float operator[](int axis) const { return axis == 0 ? x : y; }
    constexpr float& operator[](int axis) { return axis == 0 ? x : y; }

    friend constexpr bool operator==(Vec2 a, Vec2 b) = default;
};

constexpr Vec2 operator+(Vec2 a, Vec2 b) {
    return {a.x + b.x, a.y + b.y};
}
constexpr Vec2 operator-(Vec2 a, Vec2 b) {
    return {a.x - b.x, a.y - b.y};
}
constexpr Vec2 operator-(Vec2 a) {
    return {-a.x, -a.y};
}
constexpr Vec2 operator*(Vec2 a, float s) {
    return {a.x * s, a.y * s};
}
constexpr Vec2 operator*(float s, Vec2 a) {
    return {a.x * s, a.y * s};
}
constexpr Vec2& operator+=(Vec2& a, Vec2 b) {
    return a = a + b;
}
constexpr Vec2& operator-=(Vec2& a, Vec2 b) {
    return a = a - b;
}

constexpr float dot(Vec2 a, Vec2 b) {
    return a.x * b.x + a.y * b.y;
}
inline float length(Vec2 a) {
    return std::sqrt(a.x * a.x + a.y * a.y);
}

/// True when both components are finite (not NaN, not infinite).
inline bool isFinite(Vec2 a) {
    return std::isfinite(a.x) && std::isfinite(a.y);
}

/// The range of numbers jostle works in. Every number given to it (a coordinate, a size,
/// a speed, gravity, a mass, a density, a gravity scale, damping, dt) must have a
/// magnitude of at most kMaxMagnitude, and sizes (half extents, tile sides), densities,
/// explicit masses and dt must be at least kMinMagnitude; anything else throws
/// jostle::Error. Within this range the arithmetic of a step stays finite whatever the
/// mix (no sum overflows to infinity, no inverse mass does, no NaN appears), which the
/// fuzzers check (docs/reliability.md). A billion is far beyond any game world in pixels
/// or metres: floats there are already 64 units apart.
///
/// Bodies stay in the range too: a dynamic body's speed along each axis is held to
/// kMaxMagnitude whatever WorldDef::maxVelocity says, and a body that reaches
/// ±kMaxMagnitude on an axis stops there, at the edge of the world.
inline constexpr float kMaxMagnitude = 1e9f;
inline constexpr float kMinMagnitude = 1e-9f;

/// True when |v| <= kMaxMagnitude (false for NaN and infinities).
inline bool inRange(float v) {
    return std::abs(v) <= kMaxMagnitude;
}
inline bool inRange(Vec2 a) {
    return inRange(a.x) && inRange(a.y);
}

JOSTLE_EXPORT_END
} // namespace jostle
