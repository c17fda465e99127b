// A contact of two sharp boxes along an axis, as every stage that makes one makes it: its
// axis, signs, extent, slop, friction and the tangent speed friction keeps. Inline: the
// contact build makes one for each pair.
#pragma once

#include "../characters.hpp"
#include "contact.hpp"
#include "step_context.hpp"

#include <algorithm>
#include <cmath>

namespace jostle {

/// Two bodies' frictions combined by the world's rule (PhysicalOptions::frictionMix).
inline float combineFriction(FrictionMix mix, float a, float b) {
    return mix == FrictionMix::GeometricMean ? std::sqrt(a * b) : std::min(a, b);
}

/// The friction of a pair touching along `normal` (from b towards a): each body's against
/// the surface it meets (a character's wallFriction off its floor), combined.
inline float frictionOfPair(const StepContext& step, const Body& a, const Body& b, Vec2 normal) {
    const Vec2 down = step.world.events.down;
    return combineFriction(step.options.frictionMix, frictionAgainst(a, normal, down),
                           frictionAgainst(b, -normal, down));
}

/// A contact of `a` and `b` along `normal` (a unit axis vector, from b towards a): its
/// axis, signs, extent, slop and friction, and the tangent speed a character's walk or a
/// conveyor keeps; the rest left to the caller.
inline Contact contactOf(const StepContext& step, const Body& a, const Body& b, Vec2 normal) {
    Contact c;
    const bool alongX = normal.x != 0.0f;
    c.axis = alongX ? kAlongX : kAlongY;
    c.n = axisNormal(c.axis, alongX ? normal.x : normal.y);
    c.extent = alongX ? a.half.x + b.half.x : a.half.y + b.half.y;
    c.size = alongX ? std::min(a.half.x, b.half.x) : std::min(a.half.y, b.half.y);
    if (keepsATangentSpeed(a, b, step.world.conveyors > 0)) {
        // Characters rub only on floors, and walk over them; conveyors carry what rubs on
        // them (characters.hpp).
        const Vec2 down = step.world.events.down;
        c.friction = frictionOfPair(step, a, b, normal);
        Vec2 tangent;
        tangent[1 - c.axis] = c.tangentSign();
        c.tangentTarget = dot(walkOver(a, b, normal, down), tangent);
    } else {
        c.friction = combineFriction(step.options.frictionMix, a.friction, b.friction);
    }
    return c;
}

} // namespace jostle
