// The contact solver: sequential impulses over the step's contacts, and shock
// propagation. Impulses are clamped by clamping their change, not by clamping the sum
// and taking the difference: a light body under a heavy one needs a change far below the
// float step of the impulse that holds the heavy one up (docs/physical-model.md).
#include "contact_solver.hpp"

#include "step_context.hpp"

#include <algorithm>

namespace jostle {

namespace {

/// Applies `impulse` to both bodies of `c` along `axis`, as step_context.hpp's
/// applyImpulse: an infinitely heavy body is left alone.
void applyImpulse(StepContext& step, const Contact& c, int axis, float impulse) {
    SolverBody& a = step.bodies[c.ia];
    if (a.invMass > 0.0f)
        a.velocity[axis] += impulse * a.invMass;
    SolverBody& b = step.bodies[c.ib];
    if (b.invMass > 0.0f)
        b.velocity[axis] -= impulse * b.invMass;
}

float relativeSpeed(const StepContext& step, const Contact& c, int axis) {
    return step.bodies[c.ia].velocity[axis] - step.bodies[c.ib].velocity[axis];
}

float relativeSpeed(const StepContext& step, const Contact& c, Vec2 direction) {
    return dot(step.velocityOf(c.ia) - step.velocityOf(c.ib), direction);
}

/// The most a warm start takes of a cached impulse: what changes the lighter body's velocity
/// by kMaxMagnitude squared. A restored snapshot may hold any finite impulse, and a larger
/// one would overflow the step's arithmetic (a velocity, a separation); what the steps of a
/// world in math.hpp's range keep stays far below it, so it holds their bits.
void takeAtMostTheLargestImpulse(StepContext& step, Contact& c) {
    constexpr float kLargestChange = kMaxMagnitude * kMaxMagnitude;
    const float invMass = std::max(step.invMassA(c), step.invMassB(c));
    const float largest = std::max(std::abs(c.normalImpulse), std::abs(c.tangentImpulse));
    if (largest * invMass <= kLargestChange) [[likely]]
        return;
    const float most = kLargestChange / invMass;
    c.normalImpulse = std::min(c.normalImpulse, most);
    c.tangentImpulse = std::clamp(c.tangentImpulse, -most, most);
}

void warmStart(StepContext& step) {
    forEachContact(step, [&](Contact& c) {
        takeAtMostTheLargestImpulse(step, c);
        if (c.axis == kAlongSlope) {
            applyImpulse(step, c, c.n, c.normalImpulse);
            applyImpulse(step, c, c.tangent(), c.tangentImpulse);
            return;
        }
        applyImpulse(step, c, c.axis, c.sign() * c.normalImpulse);
        applyImpulse(step, c, 1 - c.axis, c.tangentSign() * c.tangentImpulse);
    });
}

/// velocityPass for a contact along a slope or a rounded corner: the same, along its
/// normal and tangent.
void solveSloped(StepContext& step, Contact& c) {
    const float effectiveMass = step.effectiveMassOf(c);
    float normalSpeed;
    {
        const float speed = relativeSpeed(step, c, c.n);
        const float impulse = std::max(-effectiveMass * (speed - c.targetSpeed), -c.normalImpulse);
        applyImpulse(step, c, c.n, impulse);
        c.normalImpulse += impulse;
        normalSpeed = speed + impulse / effectiveMass;
    }
    {
        const Vec2 tangent = c.tangent();
        const float speed = relativeSpeed(step, c, tangent);
        const float limit = c.friction * c.normalImpulse;
        const float target = c.tangentTargetAt(normalSpeed, step.right());
        const float impulse = std::clamp(-effectiveMass * (speed - target),
                                         -limit - c.tangentImpulse, limit - c.tangentImpulse);
        applyImpulse(step, c, tangent, impulse);
        c.tangentImpulse = std::clamp(c.tangentImpulse + impulse, -limit, limit);
    }
}

void velocityPass(StepContext& step) {
    forEachContact(step, [&](Contact& c) {
        if (c.axis == kAlongSlope) {
            solveSloped(step, c);
            return;
        }
        const float effectiveMass = step.effectiveMassOf(c);
        const float sign = c.sign();
        // Normal: push (never pull) until the pair stops approaching.
        {
            const float speed = sign * relativeSpeed(step, c, c.axis);
            const float impulse =
                std::max(-effectiveMass * (speed - c.targetSpeed), -c.normalImpulse);
            applyImpulse(step, c, c.axis, sign * impulse);
            c.normalImpulse += impulse;
        }
        // Friction: stop the sliding, within Coulomb's cone.
        {
            const int tangent = 1 - c.axis;
            const float speed = c.tangentSign() * relativeSpeed(step, c, tangent);
            const float limit = c.friction * c.normalImpulse;
            const float impulse = std::clamp(-effectiveMass * (speed - c.tangentTarget),
                                             -limit - c.tangentImpulse, limit - c.tangentImpulse);
            applyImpulse(step, c, tangent, c.tangentSign() * impulse);
            c.tangentImpulse = std::clamp(c.tangentImpulse + impulse, -limit, limit);
        }
    });
}

} // namespace

void solveVelocities(StepContext& step) {
    warmStart(step);
    for (int i = 0; i < step.options.velocityIterations; ++i)
        velocityPass(step);
}

void propagateShock(StepContext& step) {
    forEachContact(step, [&](Contact& c) {
        if (c.supporter == 0)
            return;
        // The supporter is held fixed: the other body takes the whole impulse.
        const float invMass = c.supporter == 1 ? step.invMassB(c) : step.invMassA(c);
        if (invMass <= 0.0f)
            return;
        if (c.axis == kAlongSlope) {
            const float speed = relativeSpeed(step, c, c.n);
            const float impulse = std::max(-(speed - c.targetSpeed) / invMass, -c.normalImpulse);
            SolverBody& held = step.bodies[c.supporter == 1 ? c.ib : c.ia];
            const float sign = c.supporter == 1 ? -1.0f : 1.0f;
            held.velocity[0] += sign * c.n.x * impulse * invMass;
            held.velocity[1] += sign * c.n.y * impulse * invMass;
            c.shockImpulse = impulse;
            return;
        }
        const float speed = c.sign() * relativeSpeed(step, c, c.axis);
        const float impulse = std::max(-(speed - c.targetSpeed) / invMass, -c.normalImpulse);
        if (c.supporter == 1)
            step.bodies[c.ib].velocity[c.axis] -= c.sign() * impulse * invMass;
        else
            step.bodies[c.ia].velocity[c.axis] += c.sign() * impulse * invMass;
        // Kept apart from the impulse both bodies felt: the held body felt none of it, and
        // warm starting the next step with it would fling a much lighter held body.
        c.shockImpulse = impulse;
    });
}

} // namespace jostle
