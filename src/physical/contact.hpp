// The physical step's working vocabulary: solver bodies and contacts. Every stage reads
// and writes these; src/physical/step.cpp lists the stages.
#pragma once

#include "../geometry.hpp"
#include "jostle/math.hpp"

#include <cstdint>

namespace jostle {

/// What the solver passes need of a body, packed together so that the passes over
/// thousands of contacts read few cache lines.
struct SolverBody {
    float velocity[2]; ///< x, y: indexed by a contact's axis
    float position[2];
    float invMass;
    std::uint32_t slot;
};

/// Two bodies touching, or about to within the step, along one normal. Bodies do not
/// rotate, so a contact is one normal and one tangent, and its effective mass is
/// 1 / (invMassA + invMassB) and nothing else: the solver bodies' (StepContext::
/// effectiveMassOf). Between boxes the normal lies along x or y, and the passes work on
/// that axis alone; a slope or a rounded corner gives any other normal (axis kAlongSlope).
/// 64 bytes, a cache line: the passes read thousands of them.
struct Contact {
    std::uint32_t ia, ib; ///< solver bodies; a is the body created first
    /// The normal points from b towards a along one axis (kAlongX, kAlongY), or along
    /// `normal()` (kAlongSlope). The tangent is the normal turned a quarter, (-ny, nx).
    Axis axis;
    /// Which body holds the other, staying put in shock propagation and position
    /// correction (support.hpp says when): 0 none, 1 a, 2 b.
    std::uint8_t supporter = 0;
    /// tangentTarget is a character's walk along a sloped floor (characters.hpp's
    /// walkAlongSlope): at rest on the floor along the normal, and set by how fast the two
    /// move along it.
    bool walksAlongSlope = false;
    /// The unit normal (along x or y: its axis's component is sign(), the other 0).
    Vec2 n;
    /// The value of the centres' offset along the normal, (a - b) · normal, at which the
    /// two touch: the sum of the half extents between boxes.
    float extent;
    float friction;
    /// The relative normal velocity must end >= this: 0 to stop, -gap/dt to let a
    /// speculative contact close its gap. Bounces are the impacts stage's.
    float targetSpeed;
    float normalImpulse = 0.0f; ///< of the sequential impulses: both bodies felt it
    float shockImpulse = 0.0f;  ///< added by shock propagation: the held body felt none
    float tangentImpulse = 0.0f;
    /// The relative tangent speed friction keeps (along the tangent, with its sign): 0,
    /// or a character's walk over its floor.
    float tangentTarget = 0.0f;
    float bounce = 0.0f; ///< the pair's restitution (the larger, or pre-solve's)
    /// Of the impacts stage (impacts.hpp): both bodies felt it; not warm-started.
    float collisionImpulse = 0.0f;
    float approachSpeed = 0.0f; ///< how fast the pair closed when the step began (>= 0)
    /// The smaller body's reach along the normal (between boxes, the smaller half extent
    /// along the axis): the overlap left alone, the slop, is WorldOptions::slop times it
    /// (StepContext::slopOf).
    float size = 0.0f;

    /// Along x or y: the normal's sign along its axis (±1, or nearly for a round shape's).
    float sign() const { return n[axis]; }
    /// Along x or y: the tangent's sign along the other axis.
    float tangentSign() const { return axis == kAlongY ? -n.y : n.x; }
    Vec2 normal() const { return n; }
    Vec2 tangent() const { return {-n.y, n.x}; }
    /// The tangent speed friction keeps when the pair moves along the normal at
    /// `normalSpeed`: tangentTarget, but for a character walking along a sloped floor, which
    /// moves across gravity (along `right`) at its walk speed whatever part of its motion is
    /// along the normal.
    float tangentTargetAt(float normalSpeed, Vec2 right) const {
        if (!walksAlongSlope)
            return tangentTarget;
        return tangentTarget - normalSpeed * dot(n, right) / dot(tangent(), right);
    }
    /// The normal impulse of the step, what the held body's partner felt.
    float totalImpulse() const { return normalImpulse + shockImpulse + collisionImpulse; }
};
static_assert(sizeof(Contact) == 64, "a contact fills one cache line");

/// The normal along `axis` (kAlongX or kAlongY) with `sign`: the other component +0.
inline Vec2 axisNormal(Axis axis, float sign) {
    return axis == kAlongX ? Vec2{sign, 0.0f} : Vec2{0.0f, sign};
}

} // namespace jostle
