// Impacts: pairwise collisions, swept until no pair of the step still meets.
#include "impacts.hpp"

#include "step_context.hpp"

#include <algorithm>
#include <cmath>

namespace jostle {

namespace {

/// Sweeps over the contacts, at most: a row of touching boxes passes a blow one box a
/// sweep whichever way the contacts are ordered.
constexpr int kMaxSweeps = 32;

/// Meeting slower than this fraction of the contact's slop per second is not meeting:
/// float noise in the velocities of a resting pile.
constexpr float kStillPerSlop = 0.5f;

Vec2 gravityOn(const StepContext& step, std::uint32_t solverBody) {
    const Body& body = step.world.slots[step.bodies[solverBody].slot];
    return body.isDynamic() ? step.world.def.gravity * body.gravityScale : Vec2{};
}

void applyImpulse(StepContext& step, const Contact& c, Vec2 direction, float impulse) {
    SolverBody& a = step.bodies[c.ia];
    SolverBody& b = step.bodies[c.ib];
    a.velocity[0] += direction.x * impulse * c.invMassA;
    a.velocity[1] += direction.y * impulse * c.invMassA;
    b.velocity[0] -= direction.x * impulse * c.invMassB;
    b.velocity[1] -= direction.y * impulse * c.invMassB;
}

/// Moves both bodies of `c` so that their offset along the normal changes by `shift`,
/// shared by inverse mass.
void shiftApart(StepContext& step, const Contact& c, Vec2 normal, float shift) {
    const float shiftA = shift * c.invMassA * c.effectiveMass;
    const float shiftB = shift * c.invMassB * c.effectiveMass;
    for (auto [solverBody, by] : {std::pair{c.ia, shiftA}, std::pair{c.ib, -shiftB}}) {
        SolverBody& s = step.bodies[solverBody];
        s.position[0] += normal.x * by;
        s.position[1] += normal.y * by;
        Body& body = step.world.slots[s.slot];
        body.position += normal * by;
    }
}

/// Collides the pair of `c` if it meets this step; true if it did. `shifted` is set if it
/// moved the bodies.
bool collide(StepContext& step, Contact& c, float threshold, bool& shifted) {
    const Vec2 n = c.normal();
    const float vn = dot(step.velocityOf(c.ia) - step.velocityOf(c.ib), n);
    // What this step's gravity adds to their approach is the contacts' to hold, not a blow.
    const float fromGravity =
        std::min(0.0f, dot(gravityOn(step, c.ia) - gravityOn(step, c.ib), n)) * step.dt;
    const float approach = fromGravity - vn;
    if (!(approach > kStillPerSlop * c.slop))
        return false;
    const float bounce = approach > threshold ? c.bounce : 0.0f;
    const float gap = -step.overlapOf(c);
    // A pair still apart meets if it closes its gap within the step.
    if (gap > 0.0f && -vn * step.dt <= gap)
        return false;
    float impulse;
    float meetAfter = 0.0f;
    if (gap > 0.0f && bounce <= 0.0f) {
        // Without a bounce: it closes the gap by the end of the step, and meets no faster.
        impulse = c.effectiveMass * (-gap / step.dt - vn);
    } else {
        // They part at `bounce` times the speed they met at, from the moment they met (in
        // which gravity has acted for part of the step only).
        meetAfter = gap > 0.0f ? gap / -vn : 0.0f;
        const float meeting = approach - fromGravity * meetAfter / step.dt;
        impulse = (1.0f + bounce) * c.effectiveMass * meeting;
    }
    applyImpulse(step, c, n, impulse);
    c.collisionImpulse += impulse;
    // Friction stops the sliding, within Coulomb's cone of the blow.
    const Vec2 t = c.tangent();
    const float leaving = dot(step.velocityOf(c.ia) - step.velocityOf(c.ib), n);
    const float slide = dot(step.velocityOf(c.ia) - step.velocityOf(c.ib), t) -
                        c.tangentTargetAt(leaving, step.right());
    const float limit = c.friction * impulse;
    applyImpulse(step, c, t, std::clamp(-c.effectiveMass * slide, -limit, limit));
    if (meetAfter > 0.0f) {
        // Met after meetAfter, then parted at the speed it left with: where that ends the
        // step, not a gap's width further off.
        shiftApart(step, c, n, -gap - leaving * meetAfter);
        shifted = true;
    }
    return true;
}

} // namespace

void resolveImpacts(StepContext& step) {
    const float threshold = step.restitutionThreshold();
    bool shifted = false;
    for (int sweep = 0; sweep < kMaxSweeps; ++sweep) {
        bool met = false;
        for (Contact& c : step.contacts)
            met = collide(step, c, threshold, shifted) || met;
        if (!met)
            break;
    }
    // The gaps the contacts may close are those between the bodies as they are now.
    if (shifted)
        for (Contact& c : step.contacts)
            if (c.targetSpeed <= 0.0f)
                c.targetSpeed = std::min(0.0f, step.overlapOf(c) / step.dt);
}

} // namespace jostle
