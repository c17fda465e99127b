// Snapping to the ground: the cast down, the move, the velocity along the floor.
#include "snap.hpp"

#include "../events.hpp"
#include "../first_stop.hpp"
#include "../one_way.hpp"
#include "continuous.hpp"
#include "sleep.hpp"
#include "step_context.hpp"
#include "support.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace jostle {

namespace {

/// Whether the body in `slot` moves away from the ground it stood on at the end of the
/// last step (jumps, bounces off it), or had none.
bool leavesGround(const WorldState& w, std::uint32_t slot) {
    const GroundRecord ground = groundOf(w, w.idOf(slot));
    if (ground.body.isNull())
        return true;
    const Body& body = w.slots[slot];
    const Vec2 relative = body.velocity - w.slots[ground.body.index].velocity;
    return dot(relative, ground.normal) > restingSpeed(body);
}

/// The normal along which a cast met `m`: a box meeting a box, the hit's axis; else where
/// the two touch.
Vec2 normalOf(const WorldState& w, const Met& m, float radius) {
    return m.contact.axis != kAlongSlope && radius == 0.0f && w.slots[m.slot].isBox()
               ? m.contact.normal
               : m.contact.touching;
}

/// The floor the body in `slot` first meets moving down by `motion`: what stops it (one-way
/// platforms and segments from their blocking side, unless it drops through them), pushing
/// it as a floor. Nothing if it touches one already, or if what it meets first is no floor.
std::optional<Met> floorBelow(const StepContext& step, std::uint32_t slot, Vec2 motion) {
    const WorldState& w = step.world;
    const Body& body = w.slots[slot];
    const float radius = body.shape == ShapeKind::Round ? w.shapes[slot].radius : 0.0f;
    std::optional<Met> first;
    auto consider = [&](std::uint32_t other) {
        const Body& obstacle = w.slots[other];
        if (other == slot || !w.isLive(other) || obstacle.sensor || !canCollide(body, obstacle))
            return;
        std::optional<Met> met = castAgainst(w, other, body.position, body.half, radius, motion);
        if (!met || !stops(obstacle, met->contact.normal, true, body.dropThroughTime))
            return;
        met->created = w.created[other];
        if (!first || met->contact.time < first->contact.time ||
            (met->contact.time == first->contact.time && met->created < first->created))
            first = met;
    };
    const Box below = sweptBox(body.position, body.half, motion);
    w.restingGrid.query(below, [&](std::uint32_t i) { consider(w.restingSlots[i]); });
    w.movingGrid.query(below, [&](std::uint32_t i) { consider(w.movingSlots[i]); });
    if (!first || first->contact.time <= 0.0f ||
        surfaceOf(normalOf(w, *first, radius), w.events.down, body.floorCos) != kFloor)
        return std::nullopt;
    return first;
}

/// How far `body` may be moved down onto a floor in a step of `dt`: its snapDown, and for
/// a character at least the drop a step at its walk speed meets on the steepest floor it
/// stands on, |walk| dt tan(floorAngle) (at most its half extent along gravity), so that
/// it follows every floor it can walk on over a crest, and a step down no taller than its
/// `stepUp` (BodyDef::stepUp) while it walks.
float snapDistance(const Body& body, float stepUp, float dt, Vec2 down) {
    if (!body.isCharacter())
        return body.snapDown;
    const float c = body.floorCos;
    const float drop = std::abs(body.walkSpeed) * dt * std::sqrt(1.0f - c * c) / c;
    const float half = std::abs(down.x) * body.half.x + std::abs(down.y) * body.half.y;
    const float steps = body.walkSpeed != 0.0f ? stepUp : 0.0f;
    return std::max({body.snapDown, std::min(drop, half), steps});
}

/// Turns the velocity of `body` along the floor of normal `n` moving at `floorVelocity`:
/// a character keeps its speed across gravity (its walk), any other body its speed.
void followFloor(Body& body, Vec2 n, Vec2 floorVelocity, Vec2 down) {
    const Vec2 relative = body.velocity - floorVelocity;
    const float away = dot(relative, n);
    if (!(away > 0.0f))
        return;
    if (body.isCharacter()) {
        body.velocity += down * (away / -dot(down, n));
        return;
    }
    const Vec2 along = relative - n * away;
    const float alongSpeed = length(along);
    if (alongSpeed > 0.0f)
        body.velocity = floorVelocity + along * (length(relative) / alongSpeed);
}

} // namespace

void snapToGround(StepContext& step) {
    WorldState& w = step.world;
    if (w.snappingBodies == 0)
        return;
    ContinuousScratch& found = step.scratch.continuous;
    for (std::uint32_t slot : w.movingSlots) {
        Body& body = w.slots[slot];
        const float distance = snapDistance(body, w.asGiven[slot].stepUp, step.dt, w.events.down);
        if (!body.isDynamic() || !(distance > 0.0f) || !w.isLive(slot) || leavesGround(w, slot))
            continue;
        const Vec2 motion = w.events.down * distance;
        const std::optional<Met> floor = floorBelow(step, slot, motion);
        if (!floor)
            continue;
        const float radius = body.shape == ShapeKind::Round ? w.shapes[slot].radius : 0.0f;
        const Vec2 before = body.position;
        body.position = touchingAt(w, body.position + motion * floor->contact.time, body.half,
                                   radius, motion, *floor);
        const Vec2 n = normalOf(w, *floor, radius);
        const std::uint32_t solverBody = step.scratch.solverIndex[slot];
        if (solverBody != StepContext::kNoSolverBody) {
            step.bodies[solverBody].position[0] = body.position.x;
            step.bodies[solverBody].position[1] = body.position.y;
        }
        body.separation += body.position - before;
        const Body& obstacle = w.slots[floor->slot];
        followFloor(body, n, obstacle.surfaceMotion(n), w.events.down);
        const float size = std::min(reachOf(body.half, w.shapes[slot], n),
                                    reachOf(obstacle.half, w.shapes[floor->slot], n));
        found.sweepStart = found.found.size();
        addFoundContact(step, slot, {floor->contact, floor->slot, floor->contact.extent, size},
                        0.0f);
    }
    if (!found.found.empty()) {
        step.contacts.insert(step.contacts.end(), found.found.begin(), found.found.end());
        found.found.clear();
    }
}

} // namespace jostle
