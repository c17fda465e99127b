// The physical model's step: its stages, in order, over one context. Each stage is in the
// file its header names; docs/architecture.md follows the data through them.
#include "step.hpp"

#include "../broadphase.hpp"
#include "../characters.hpp"
#include "../integrate.hpp"
#include "../stopwatch.hpp"
#include "contact_cache.hpp"
#include "contact_solver.hpp"
#include "contacts.hpp"
#include "continuous.hpp"
#include "corners.hpp"
#include "impacts.hpp"
#include "riders.hpp"
#include "positions.hpp"
#include "report.hpp"
#include "sleep.hpp"
#include "snap.hpp"
#include "solver_layers.hpp"
#include "step_context.hpp"
#include "support.hpp"

#include <cstddef>

namespace jostle {

void stepPhysical(WorldState& world, float dt) {
    StepContext step(world, dt);
    StepProfile& time = world.profile;
    Stopwatch clock;
    world.events.beginStep(world);
    time.events += clock.lap();
    carryRiders(step);
    time.positions += clock.lap();
    applyForces(world, dt);
    integrateAwakeBodies(world, dt);
    walkCharacters(world);
    time.velocities += clock.lap();
    findPairs(world, dt, world.pairs);
    time.pairs += clock.lap();
    slipRoundCorners(step);
    buildContacts(step);
    time.contacts += clock.lap();
    orderBySupport(step);
    time.support += clock.lap();
    resolveImpacts(step);
    time.impacts += clock.lap();
    layerContacts(step);
    time.support += clock.lap();
    solveVelocities(step);
    propagateShock(step);
    settleBounces(step);
    time.velocities += clock.lap();
    const std::size_t layered = step.contacts.size();
    sweepFastBodies(step);
    time.sweeps += clock.lap();
    integratePositions(step);
    time.positions += clock.lap();
    if (step.contacts.size() != layered)
        layerContacts(step); // the sweep added contacts at the end
    time.support += clock.lap();
    correctPositions(step);
    snapToGround(step);
    time.positions += clock.lap();
    storeImpulses(step);
    time.store += clock.lap();
    reportEvents(step);
    time.events += clock.lap();
    rememberPlatformVelocities(step);
    time.store += clock.lap();
    if (world.def.sleeping)
        fallAsleep(step);
    time.sleep += clock.lap();
    // Kinematic bodies count: sensors see them.
    world.events.publish(world, !world.movingSlots.empty());
    time.events += clock.lap();
}

} // namespace jostle
