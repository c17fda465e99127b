// Impacts: pairwise collisions, swept until no pair of the step still meets.
#include "impacts.hpp"

#include "step_context.hpp"
#include "support.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <utility>
#include <vector>

namespace jostle {

namespace {

/// Sweeps over the contacts, at most: a row of touching boxes passes a blow one box a
/// sweep whichever way the contacts are ordered.
constexpr int kMaxSweeps = 8;

/// A body met this many times in one step is in a rattle (collide): as many as the sweeps.
constexpr int kRattleMeetings = kMaxSweeps;

/// Meeting slower than this fraction of the contact's slop per second is not meeting:
/// float noise in the velocities of a resting pile.
constexpr float kStillPerSlop = 5.0f;

/// Moves the bodies of `c` so that their offset along the normal changes by `shift`,
/// body A taking `shareA` of it and body B `shareB`.
void shiftApart(StepContext& step, const Contact& c, Vec2 normal, float shift, float shareA,
                float shareB) {
    for (auto [solverBody, by] :
         {std::pair{c.ia, shift * shareA}, std::pair{c.ib, -shift * shareB}}) {
        SolverBody& s = step.bodies[solverBody];
        s.position[0] += normal.x * by;
        s.position[1] += normal.y * by;
        Body& body = step.world.slots[s.slot];
        body.position += normal * by;
    }
}

/// Whether the pair of `c` approaches faster than the noise of a resting pile: collide's
/// first test, worked out along the contact's axis (the same comparison, but for the sign
/// of a zero), so that the many contacts that do not meet cost little.
inline bool mayMeet(const StepContext& step, const Contact& c) {
    if (c.axis == kAlongSlope)
        return true;
    const std::vector<Vec2>& gravity = step.scratch.impacts.gravityInStep;
    const auto along = [&](Vec2 v) { return c.axis == kAlongX ? v.x : v.y; };
    const float vn =
        c.sign() * (step.bodies[c.ia].velocity[c.axis] - step.bodies[c.ib].velocity[c.axis]);
    const float fromGravity =
        std::min(0.0f, c.sign() * (along(gravity[c.ia]) - along(gravity[c.ib])));
    return fromGravity - vn > kStillPerSlop * step.slopOf(c);
}

/// Collides the pair of contact `k` if it meets this step; true if it did. `shifted` is set
/// if it moved the bodies.
bool collide(StepContext& step, std::uint32_t k, float threshold, bool& shifted) {
    Contact& c = step.contacts[k];
    const Vec2 n = c.normal();
    const float vn = dot(step.velocityOf(c.ia) - step.velocityOf(c.ib), n);
    // What this step's gravity adds to their approach is the contacts' to hold, not a blow.
    const std::vector<Vec2>& gravity = step.scratch.impacts.gravityInStep;
    const float fromGravity = std::min(0.0f, dot(gravity[c.ia] - gravity[c.ib], n));
    const float approach = fromGravity - vn;
    if (!(approach > kStillPerSlop * step.slopOf(c)))
        return false;
    const float gap = -step.overlapOf(c);
    // A pair still apart meets if it closes its gap within the step.
    if (gap > 0.0f && -vn * step.dt <= gap)
        return false;
    std::vector<ImpactsScratch::OfBody>& ofBody = step.scratch.impacts.ofBody;
    // A body that has met kRattleMeetings times in the step is in a rattle (a light body
    // between a heavy one and a held one is met some pi sqrt(M / m) times before they part,
    // more than the sweeps follow): its meetings from then on do not bounce (inelastic
    // collapse).
    bool rattling = false;
    for (std::uint32_t body : {c.ia, c.ib})
        if (step.bodies[body].invMass > 0.0f) {
            std::uint8_t& meetings = ofBody[body].meetings;
            rattling = rattling || meetings == kRattleMeetings;
            meetings = static_cast<std::uint8_t>(std::min(meetings + 1, kRattleMeetings));
        }
    const float bounce = approach > threshold && !rattling ? c.bounce : 0.0f;
    float impulse;
    float meetAfter = 0.0f;
    // A pair meets no earlier than its bodies' last change across it (along its axis; both
    // for a slope): its path before then is not the one their velocities now give.
    const auto across = [&](Vec2 at) {
        return c.axis == kAlongSlope ? std::max(at.x, at.y) : c.axis == kAlongX ? at.x : at.y;
    };
    const float since = std::max(across(ofBody[c.ia].changedAt), across(ofBody[c.ib].changedAt));
    if (gap > 0.0f && bounce <= 0.0f && since <= 0.0f) {
        // Without a bounce: it closes the gap by the end of the step, and meets no faster.
        impulse = step.effectiveMassOf(c) * (-gap / step.dt - vn);
    } else {
        // They part at `bounce` times the speed they met at, from the moment they met (in
        // which gravity has acted for part of the step only).
        meetAfter = std::max(gap > 0.0f ? gap / -vn : 0.0f, since);
        const float meeting = approach - fromGravity * meetAfter / step.dt;
        impulse = (1.0f + bounce) * step.effectiveMassOf(c) * meeting;
    }
    applyImpulse(step, c, n, impulse);
    c.collisionImpulse += impulse;
    // Friction stops the sliding, within Coulomb's cone of the blow.
    const Vec2 t = c.tangent();
    const float leaving = dot(step.velocityOf(c.ia) - step.velocityOf(c.ib), n);
    const float slide = dot(step.velocityOf(c.ia) - step.velocityOf(c.ib), t) -
                        c.tangentTargetAt(leaving, step.right());
    const float limit = c.friction * impulse;
    const float rub = std::clamp(-step.effectiveMassOf(c) * slide, -limit, limit);
    applyImpulse(step, c, t, rub);
    // What friction changed, which no shift follows: settleBounces takes it back.
    ofBody[c.ia].rubbed += t * (rub * step.invMassA(c));
    ofBody[c.ib].rubbed -= t * (rub * step.invMassB(c));
    if (meetAfter > 0.0f) {
        // Met after meetAfter, then parted at the speed it left with: where that ends the
        // step, not a gap's width further off. Each body is moved by its own velocity change
        // times the moment they met, so that each one's path passes through the meeting point.
        const float m = step.effectiveMassOf(c);
        shiftApart(step, c, n, (vn - leaving) * meetAfter, step.invMassA(c) * m,
                   step.invMassB(c) * m);
        for (std::uint32_t body : {c.ia, c.ib})
            if (step.bodies[body].invMass > 0.0f) {
                Vec2& at = ofBody[body].changedAt;
                if (c.axis != kAlongY)
                    at.x = meetAfter;
                if (c.axis != kAlongX)
                    at.y = meetAfter;
            }
        step.scratch.impacts.bounced.push_back(
            {k, meetAfter, leaving, ofBody[c.ia].rubbed - ofBody[c.ib].rubbed});
        shifted = true;
    }
    return true;
}

} // namespace

void resolveImpacts(StepContext& step) {
    ImpactsScratch& s = step.scratch.impacts;
    const std::size_t bodyCount = step.bodies.size();
    s.gravityInStep.resize(bodyCount);
    step.world.tasks->forEachBlock(std::uint32_t(bodyCount), kBodiesPerBlock, [&](Block block) {
        for (std::uint32_t k = block.begin; k < block.end; ++k) {
            const Body& body = step.world.slots[step.bodies[k].slot];
            s.gravityInStep[k] =
                body.isDynamic() ? step.world.def.gravity * (body.gravityScale * step.dt) : Vec2{};
        }
    });
    s.ofBody.assign(bodyCount, ImpactsScratch::OfBody{});
    const float threshold = step.restitutionThreshold();
    bool shifted = false;
    // Notes the bodies of a contact that collided in `sweep`, once each.
    auto noteChanged = [&](const Contact& c, int sweep) {
        for (std::uint32_t body : {c.ia, c.ib})
            if (s.ofBody[body].changedInSweep != sweep) {
                s.ofBody[body].changedInSweep = sweep;
                s.next.push_back(body);
            }
    };
    // The first sweep looks at every contact.
    s.next.clear();
    s.bounced.clear();
    for (std::uint32_t k = 0; k < step.contacts.size(); ++k)
        if (mayMeet(step, step.contacts[k]) && collide(step, k, threshold, shifted))
            noteChanged(step.contacts[k], 1);
    // Each later one at the contacts of the bodies the one before changed, in order: the
    // support order's contact graph lists each body's.
    const SupportScratch& graph = step.scratch.support;
    for (int sweep = 2; sweep <= kMaxSweeps && !s.next.empty(); ++sweep) {
        s.changed.swap(s.next);
        s.next.clear();
        // The contacts of the changed bodies, each once, in the order of the contacts.
        s.queued.resize((step.contacts.size() + 63) / 64); // all 0: each word is cleared as read
        for (std::uint32_t body : s.changed)
            for (std::uint32_t e = graph.graph.begin(body); e < graph.graph.end(body); ++e) {
                const std::uint32_t k = graph.sortedPlace[graph.edgeContact[e]];
                s.queued[k / 64] |= std::uint64_t{1} << (k % 64);
            }
        for (std::size_t word = 0; word < s.queued.size(); ++word)
            for (std::uint64_t bits = std::exchange(s.queued[word], 0); bits != 0;
                 bits &= bits - 1) {
                const auto k = std::uint32_t(word * 64 + std::size_t(std::countr_zero(bits)));
                if (mayMeet(step, step.contacts[k]) && collide(step, k, threshold, shifted))
                    noteChanged(step.contacts[k], sweep);
            }
    }
    // What the contacts may take back of a bounce is what they change of the pair's
    // parting after every collision of the step (a later collision's own shift counts it).
    for (ImpactsScratch::Bounced& b : s.bounced) {
        const Contact& c = step.contacts[b.contact];
        const Vec2 rubbedSince = s.ofBody[c.ia].rubbed - s.ofBody[c.ib].rubbed - b.rubbed;
        b.leaving = dot(step.velocityOf(c.ia) - step.velocityOf(c.ib) - rubbedSince, c.normal());
    }
    // The gaps the contacts may close are those between the bodies as they are now.
    if (shifted)
        for (Contact& c : step.contacts)
            if (c.targetSpeed <= 0.0f)
                c.targetSpeed = std::min(0.0f, step.overlapOf(c) / step.dt);
}

void settleBounces(StepContext& step) {
    for (const ImpactsScratch::Bounced& b : step.scratch.impacts.bounced) {
        const Contact& c = step.contacts[b.contact];
        const Vec2 n = c.normal();
        const float leaving = dot(step.velocityOf(c.ia) - step.velocityOf(c.ib), n);
        const float unmade = (b.leaving - leaving) * b.meetAfter;
        if (unmade > 0.0f)
            // As position correction moves them: the body that holds the other stays put,
            // so that taking a bounce back never drives a held body into what holds it.
            shiftApart(step, c, n, unmade, step.shareOfA(c), step.shareOfB(c));
    }
}

} // namespace jostle
