// Integration that both models share: velocities from gravity, damping and the clamp, and
// the edge of the world (math.hpp's range) that no body passes.
#pragma once

#include "jostle/math.hpp"

#include <algorithm>

namespace jostle {

struct Body;
struct WorldDef;
struct WorldState;

/// Gravity, damping and the velocity clamp for one dynamic body, as both models apply
/// them at the start of a step: the tutorial's `d.yv = d.yv + grav` and clampVec.
void integrateVelocity(const WorldDef& def, Body& body, float dt);

/// The forces applied since the last step act for this one (World::applyForce), and
/// are cleared. Both models, before they integrate velocities.
void applyForces(WorldState& world, float dt);

/// The physical model's first stage: integrateVelocity for every awake dynamic body, and
/// the time each one has left to drop through one-way platforms counts down.
void integrateAwakeBodies(WorldState& world, float dt);

/// Holds each component of a velocity to ±kMaxMagnitude (math.hpp): no speed beyond it,
/// so that no later sum overflows.
inline Vec2 withinRange(Vec2 velocity) {
    return {std::clamp(velocity.x, -kMaxMagnitude, kMaxMagnitude),
            std::clamp(velocity.y, -kMaxMagnitude, kMaxMagnitude)};
}

/// The edge of the world (math.hpp): a body beyond ±kMaxMagnitude on an axis is put back
/// on it, and loses its speed along that axis. True if it was beyond. The classic model
/// applies it after each move, so that the pre-solve callbacks it calls as it goes see no
/// body beyond the edge.
bool stopAtTheEdge(Body& body);

/// The end of every step, however it ends: no speed beyond kMaxMagnitude (so that no
/// later sum overflows), and every body stopped at the edge of the world.
void keepInsideTheWorld(WorldState& world);

} // namespace jostle
