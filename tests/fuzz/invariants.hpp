// What must hold of any world, whatever was done to it: checked by the fuzzers after each
// step and by the soak test (tests/soak) every step. Each check returns a description of
// the first violation it finds, or nothing, so that the caller decides how to fail.
#pragma once

#include "jostle/query.hpp"
#include "jostle/world.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>

namespace jostle::check {

inline std::string describe(BodyId id) {
    return "body {" + std::to_string(id.index) + ", " + std::to_string(id.generation) + ", " +
           std::to_string(id.world) + "}";
}

inline std::string describe(Vec2 v) {
    char text[64];
    std::snprintf(text, sizeof text, "(%.9g, %.9g)", static_cast<double>(v.x),
                  static_cast<double>(v.y));
    return text;
}

/// Every live body's state is made of finite numbers: position and velocity within the
/// range jostle works in (math.hpp), separation, half extents (> 0), and its mass is > 0
/// (infinity only for static and kinematic bodies: the solver divides by it).
inline std::optional<std::string> finiteState(const World& world) {
    for (BodyId id : world.bodies()) {
        if (!world.isValid(id))
            return describe(id) + " is listed by bodies() but not valid";
        const Vec2 p = world.position(id), v = world.velocity(id), h = world.halfExtents(id);
        const Vec2 s = world.separation(id);
        // Finite, and within the edge of the world (math.hpp): a body stops there, and no
        // speed goes beyond it.
        if (!inRange(p))
            return describe(id) + ": position " + describe(p);
        if (!inRange(v))
            return describe(id) + ": velocity " + describe(v);
        if (!isFinite(h) || !(h.x > 0.0f) || !(h.y > 0.0f))
            return describe(id) + ": halfExtents " + describe(h);
        if (!isFinite(s))
            return describe(id) + ": separation " + describe(s);
        const float m = world.mass(id);
        const bool heavy = world.type(id) != BodyType::Dynamic;
        if (heavy ? m != std::numeric_limits<float>::infinity() : !(m > 0.0f && std::isfinite(m)))
            return describe(id) + ": mass " + std::to_string(m);
    }
    return std::nullopt;
}

/// How deep a body sits inside a static body it collides with, and how deep the physical
/// model lets it sit at rest.
struct Penetration {
    BodyId into;
    float depth = 0.0f;
    float allowed = 0.0f;
};

/// The penetration the physical model leaves alone between two boxes at rest, along the
/// contact normal (contactAlongX): the slop, a fraction of the pair's smaller half extent on
/// that axis (docs/physical-model.md, PhysicalOptions::slop); plus what geometry.hpp calls
/// float noise, kMinimumSkin = 1e-4 of that half extent (the solver's own sums of
/// impulses and corrections round: a heavy pile on a light box rests a few 1e-6 of its
/// size beyond the slop); plus the rounding of the four floats the overlap is computed
/// from (a few units in the last place of the largest coordinate involved: far from the
/// origin a float cannot place a box closer).
inline float allowedPenetration(float slop, float halfA, float halfB, float centreA,
                                float centreB) {
    constexpr float kFloatNoise = 1e-4f; // geometry.hpp's kMinimumSkin
    const float largest = std::max({std::abs(centreA), std::abs(centreB), halfA + halfB});
    const float ulp = std::nextafter(largest, std::numeric_limits<float>::infinity()) - largest;
    return (slop + kFloatNoise) * std::min(halfA, halfB) + 4.0f * ulp;
}

/// The axis of the contact normal between two overlapping boxes, as the physical model
/// chooses it (geometry.hpp, contactAxis): overlap within the contact skin (twice the slop
/// times the smaller half extent on that axis) is touching, not penetrating. Penetrating
/// on both axes: the axis of least penetration, a tie going to y. On one axis only: the
/// boxes are side by side along the other (a box resting across the seam of two floor
/// boxes overlaps the next one's corner a little sideways, and rests on it along y).
/// Touching on both: y.
inline bool contactAlongX(float overlapX, float overlapY, float slop, Vec2 h, Vec2 k) {
    constexpr float kMinimumSkin = 1e-4f; // geometry.hpp's, of the smaller half extent
    const float skinX = std::max(2.0f * slop, kMinimumSkin) * std::min(h.x, k.x);
    const float skinY = std::max(2.0f * slop, kMinimumSkin) * std::min(h.y, k.y);
    const bool realX = overlapX > skinX, realY = overlapY > skinY;
    if (realX && realY)
        return overlapX < overlapY;
    return realY && !realX;
}

/// The deepest overlap of `body` with a static body that the two collide with (filters
/// allow it, neither is a sensor, the static one is not a one-way platform, which a body
/// may stand inside of), if it is deeper along the contact normal than allowedPenetration
/// plus `extra`.
inline std::optional<Penetration> deepInStatic(const World& world, BodyId body,
                                               float extra = 0.0f) {
    if (world.isSensor(body))
        return std::nullopt;
    const float slop = world.physicalOptions().slop;
    const Vec2 p = world.position(body), h = world.halfExtents(body);
    // The query's filter is the body's own: it reports exactly what the body collides with.
    const QueryFilter filter{
        .mask = world.mask(body), .category = world.category(body), .ignore = body};
    std::optional<Penetration> worst;
    for (BodyId other : queryBox(world, p, h, filter)) {
        if (world.type(other) != BodyType::Static || world.oneWay(other) != Vec2{})
            continue;
        const Vec2 q = world.position(other), k = world.halfExtents(other);
        // In double, where sums and differences of floats are exact: the depth changes
        // whenever a body moves, however little.
        auto overlap = [](float half, float otherHalf, float at, float otherAt) {
            return static_cast<float>(
                static_cast<double>(half) + static_cast<double>(otherHalf) -
                std::abs(static_cast<double>(at) - static_cast<double>(otherAt)));
        };
        const float overlapX = overlap(h.x, k.x, p.x, q.x);
        const float overlapY = overlap(h.y, k.y, p.y, q.y);
        const bool alongX = contactAlongX(overlapX, overlapY, slop, h, k);
        const float depth = alongX ? overlapX : overlapY;
        const float allowed = extra + (alongX ? allowedPenetration(slop, h.x, k.x, p.x, q.x)
                                              : allowedPenetration(slop, h.y, k.y, p.y, q.y));
        if (depth > allowed && (!worst || depth - allowed > worst->depth - worst->allowed))
            worst = Penetration{other, depth, allowed};
    }
    return worst;
}

} // namespace jostle::check
