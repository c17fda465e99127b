// recordContact's two halves (events.hpp), inline for the stages that record a contact
// each: what the pair is, a pure function of the world that any thread may work out, and
// listing it, on one thread, in order.
#pragma once

#include "events.hpp"
#include "world_state.hpp"

#include <cstdint>

namespace jostle {

/// What a pair touching at the end of the step records: `normal` points from `other`
/// towards `body`; the surface pushes each body away from the other, and the record lists
/// the body created first as `a`, the normal pointing towards it.
inline FoundTouch findTouch(const WorldState& world, std::uint32_t body, std::uint32_t other,
                            Vec2 normal, float approachSpeed, float impulse) {
    const StepEvents& events = world.events;
    const TouchingBit flagBody = surfaceOf(normal, events.down, world.slots[body].floorCos);
    const TouchingBit flagOther = surfaceOf(-normal, events.down, world.slots[other].floorCos);
    if (world.createdBefore(body, other))
        return {{world.refOf(body), world.refOf(other), normal, approachSpeed, impulse},
                flagBody,
                flagOther};
    return {{world.refOf(other), world.refOf(body), -normal, approachSpeed, impulse},
            flagOther,
            flagBody};
}

/// Sets the touching flags of `record`'s two bodies: `flagA` a's, `flagB` b's.
inline void flagTouch(StepEvents& events, const TouchRecord& record, TouchingBit flagA,
                      TouchingBit flagB) {
    events.touching[record.a.index] |= flagA;
    events.touching[record.b.index] |= flagB;
}

/// Lists a touch found by findTouch and sets both bodies' touching flags.
inline void listTouch(WorldState& world, const FoundTouch& touch) {
    flagTouch(world.events, touch.record, touch.flagA, touch.flagB);
    world.events.contactsNow.push_back(touch.record);
}

} // namespace jostle
