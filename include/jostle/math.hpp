// jostle/math.hpp: the one vector type of the API.
//
// jostle works in floats and in the user's units (pixels are fine). Nothing here
// is clever: a 2D vector and the few operations the library and its users need.
#pragma once

#include <cmath>

namespace jostle {

/// A 2D vector: a position, a velocity, half extents or a normal.
struct Vec2 {
    float x = 0.0f;
    float y = 0.0f;

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

} // namespace jostle
