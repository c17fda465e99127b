// Riders of kinematic bodies. Friction alone would let a rider slide until it caught up
// with a platform that started, stopped or turned.
#include "riders.hpp"

#include "step_context.hpp"

namespace jostle {

namespace {

/// Whether any kinematic body's velocity changed since the last step (a body destroyed
/// since is not one: what its slot still holds is no body's).
bool anyPlatformChanged(const WorldState& w) {
    for (std::uint32_t slot : w.movingSlots) {
        const Body& body = w.slots[slot];
        if (body.alive && body.type == BodyType::Kinematic &&
            body.velocity != body.lastStepVelocity)
            return true;
    }
    return false;
}

} // namespace

void carryRiders(StepContext& step) {
    WorldState& w = step.world;
    const Vec2 g = w.def.gravity;
    // Nothing stands on anything without gravity; no platform changed: nothing to hand on.
    if (g == Vec2{} || !anyPlatformChanged(w))
        return;
    std::vector<std::uint8_t>& carried = step.scratch.platforms.carried;
    carried.assign(w.slots.size(), 0);
    for (const TouchRecord& record : w.events.touchingBefore()) {
        if (!w.isCurrent(record.a) || !w.isCurrent(record.b))
            continue;
        Body& a = w.slots[record.a.index];
        Body& b = w.slots[record.b.index];
        const bool aRides = a.isDynamic() && b.type == BodyType::Kinematic;
        const bool bRides = b.isDynamic() && a.type == BodyType::Kinematic;
        if (!aRides && !bRides)
            continue;
        Body& rider = aRides ? a : b;
        const Body& platform = aRides ? b : a;
        // The normal points from b towards a: the push the rider gets from below.
        const Vec2 up = aRides ? record.normal : -record.normal;
        const Vec2 change = platform.velocity - platform.lastStepVelocity;
        const std::uint32_t riderSlot = aRides ? record.a.index : record.b.index;
        if (dot(up, g) >= 0.0f || change == Vec2{} || carried[riderSlot])
            continue;
        carried[riderSlot] = 1;
        rider.velocity += change;
    }
}

void rememberPlatformVelocities(StepContext& step) {
    step.world.forEachMover([](Body& body, Block) {
        if (body.type == BodyType::Kinematic)
            body.lastStepVelocity = body.velocity;
    });
}

} // namespace jostle
