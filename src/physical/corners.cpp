// Slipping round corners: see corners.hpp.
#include "corners.hpp"

#include "../broadphase.hpp"
#include "../events.hpp"
#include "step_context.hpp"

#include <cmath>
#include <cstdint>

namespace jostle {

namespace {

/// Whether a solid body other than `self` overlaps `box`: a body of the grids that collides
/// with `self` and is no sensor and no one-way platform (which stops nothing from the side).
bool somethingSolidIn(const WorldState& w, std::uint32_t self, const Box& box) {
    const Body& body = w.slots[self];
    bool found = false;
    auto consider = [&](std::uint32_t other) {
        const Body& o = w.slots[other];
        found = found || (other != self && w.isLive(other) && !o.sensor && !o.isOneWay() &&
                          canCollide(body, o) && overlaps(box, o.box()));
    };
    w.restingGrid.query(box, [&](std::uint32_t i) { consider(w.restingSlots[i]); });
    w.movingGrid.query(box, [&](std::uint32_t i) { consider(w.movingSlots[i]); });
    return found;
}

/// Moves body `mover` round the corner of `obstacle` it is about to clip, if the rules of
/// corners.hpp let it. True if it moved.
bool slip(StepContext& step, std::uint32_t mover, std::uint32_t obstacle) {
    WorldState& w = step.world;
    Body& a = w.slots[mover];
    const Body& b = w.slots[obstacle];
    const KeptAsGiven& kept = w.asGiven[mover];
    const Vec2 down = w.events.down;
    const Vec2 d = a.position - b.position;
    const Vec2 motion = (a.velocity - b.velocity) * step.dt;
    for (int k = 0; k < 2; ++k) {
        const int j = 1 - k;
        const float gapK = std::abs(d[k]) - (a.half[k] + b.half[k]);
        const float overlap = a.half[j] + b.half[j] - std::abs(d[j]);
        // Apart along k, side by side along j, reaching the face within the step.
        if (gapK < 0.0f || !(overlap > 0.0f) || d[j] == 0.0f)
            continue;
        if (!(motion[k] * (d[k] > 0.0f ? -1.0f : 1.0f) > gapK))
            continue;
        Vec2 face; // the face's normal, from the obstacle towards the body
        face[k] = d[k] > 0.0f ? 1.0f : -1.0f;
        Vec2 aside; // where the body goes round the corner
        aside[j] = d[j] > 0.0f ? 1.0f : -1.0f;
        const float faceAlongGravity = dot(face, down);
        float by = -1.0f;
        // A rising body at a ceiling, or a body moving across gravity at a wall; a floor
        // under it is a landing.
        if (kept.cornerCorrection > 0.0f && faceAlongGravity >= 0.0f &&
            overlap <= kept.cornerCorrection)
            by = overlap + step.skinOf(a.half[j], b.half[j]);
        // A character on the ground walking into a step's side, onto its top.
        const bool onTheGround = !groundOf(w, w.idOf(mover)).body.isNull();
        if (by < 0.0f && kept.stepUp > 0.0f && a.isCharacter() && onTheGround &&
            faceAlongGravity == 0.0f && dot(aside, down) < 0.0f && overlap <= kept.stepUp)
            by = overlap;
        if (by < 0.0f)
            continue;
        const Vec2 to = a.position + aside * by;
        if (somethingSolidIn(w, mover, boxAround(to, a.half)))
            continue;
        a.position = to;
        return true;
    }
    return false;
}

/// Whether `slot` may slip round the corners of `other`: a dynamic sharp box that slips,
/// awake, against a static or kinematic sharp box it collides with.
bool mayTurn(const WorldState& w, std::uint32_t slot, std::uint32_t other) {
    const Body& a = w.slots[slot];
    const Body& b = w.slots[other];
    return a.isDynamic() && !a.asleep && a.isBox() && b.isBox() && !b.isDynamic() && !a.sensor &&
           !b.sensor && !b.isOneWay() && w.asGiven[slot].slipsRoundCorners() && canCollide(a, b);
}

} // namespace

void slipRoundCorners(StepContext& step) {
    WorldState& w = step.world;
    if (w.cornerBodies == 0)
        return;
    for (const BodyPair& pair : w.pairs) {
        if (mayTurn(w, pair.a, pair.b))
            slip(step, pair.a, pair.b);
        else if (mayTurn(w, pair.b, pair.a))
            slip(step, pair.b, pair.a);
    }
}

} // namespace jostle
