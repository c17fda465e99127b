// The physical model's step: its stages, in order, over one context. Each stage is in the
// file its header names; docs/architecture.md follows the data through them.
#include "step.hpp"

#include "../broadphase.hpp"
#include "../characters.hpp"
#include "../integrate.hpp"
#include "contact_cache.hpp"
#include "contact_solver.hpp"
#include "contacts.hpp"
#include "continuous.hpp"
#include "impacts.hpp"
#include "platforms.hpp"
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
    world.events.beginStep(world);
    carryRiders(step);
    applyForces(world, dt);
    integrateAwakeBodies(world, dt);
    walkCharacters(world);
    findPairs(world, dt, world.pairs);
    buildContacts(step);
    orderBySupport(step);
    resolveImpacts(step);
    layerContacts(step);
    solveVelocities(step);
    propagateShock(step);
    const std::size_t layered = step.contacts.size();
    sweepFastBodies(step);
    integratePositions(step);
    if (step.contacts.size() != layered)
        layerContacts(step); // the sweep added contacts at the end
    correctPositions(step);
    snapToGround(step);
    storeImpulses(step);
    reportEvents(step);
    rememberPlatformVelocities(step);
    if (world.def.sleeping)
        fallAsleep(step);
    // Kinematic bodies count: sensors see them.
    world.events.publish(world, !world.movingSlots.empty());
}

} // namespace jostle
