// Impacts: pairwise collisions, swept until no pair of the step still meets.
#include "impacts.hpp"

#include "step_context.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace jostle {

namespace {

/// Sweeps over the contacts, at most: a row of touching boxes passes a blow one box a
/// sweep whichever way the contacts are ordered.
constexpr int kMaxSweeps = 8;

/// Meeting slower than this fraction of the contact's slop per second is not meeting:
/// float noise in the velocities of a resting pile.
constexpr float kStillPerSlop = 5.0f;


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
    const std::vector<Vec2>& gravity = step.scratch.impacts.gravityInStep;
    const float fromGravity = std::min(0.0f, dot(gravity[c.ia] - gravity[c.ib], n));
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
    ImpactsScratch& s = step.scratch.impacts;
    const std::size_t bodyCount = step.bodies.size();
    s.gravityInStep.resize(bodyCount);
    for (std::size_t k = 0; k < bodyCount; ++k) {
        const Body& body = step.world.slots[step.bodies[k].slot];
        s.gravityInStep[k] =
            body.isDynamic() ? step.world.def.gravity * (body.gravityScale * step.dt) : Vec2{};
    }
    s.changedInSweep.assign(bodyCount, 0);
    const float threshold = step.restitutionThreshold();
    bool shifted = false;
    // Notes the bodies of a contact that collided in `sweep`, once each.
    auto noteChanged = [&](const Contact& c, int sweep) {
        for (std::uint32_t body : {c.ia, c.ib})
            if (s.changedInSweep[body] != sweep) {
                s.changedInSweep[body] = sweep;
                s.next.push_back(body);
            }
    };
    // The first sweep looks at every contact.
    s.next.clear();
    for (Contact& c : step.contacts)
        if (collide(step, c, threshold, shifted))
            noteChanged(c, 1);
    if (!s.next.empty()) {
        // Each later one at the contacts of the bodies the one before changed, in order.
        s.byBody.reset(bodyCount);
        for (const Contact& c : step.contacts) {
            s.byBody.count(c.ia);
            s.byBody.count(c.ib);
        }
        s.contactsOf.resize(s.byBody.endCounting());
        for (std::uint32_t k = 0; k < step.contacts.size(); ++k) {
            s.contactsOf[s.byBody.place(step.contacts[k].ia)] = k;
            s.contactsOf[s.byBody.place(step.contacts[k].ib)] = k;
        }
        s.byBody.endPlacing();
    }
    for (int sweep = 2; sweep <= kMaxSweeps && !s.next.empty(); ++sweep) {
        s.changed.swap(s.next);
        s.next.clear();
        s.candidates.clear();
        for (std::uint32_t body : s.changed)
            for (std::uint32_t k = s.byBody.begin(body); k < s.byBody.end(body); ++k)
                s.candidates.push_back(s.contactsOf[k]);
        std::sort(s.candidates.begin(), s.candidates.end());
        s.candidates.erase(std::unique(s.candidates.begin(), s.candidates.end()),
                           s.candidates.end());
        for (std::uint32_t k : s.candidates)
            if (collide(step, step.contacts[k], threshold, shifted))
                noteChanged(step.contacts[k], sweep);
    }
    // The gaps the contacts may close are those between the bodies as they are now.
    if (shifted)
        for (Contact& c : step.contacts)
            if (c.targetSpeed <= 0.0f)
                c.targetSpeed = std::min(0.0f, step.overlapOf(c) / step.dt);
}

} // namespace jostle
