// The physical model's step: its stages, in order, over one context, each timed into the
// profile bucket named after it (World::profile). Each stage is in the file its header
// names; docs/architecture.md follows the data through them.
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
#include "positions.hpp"
#include "report.hpp"
#include "riders.hpp"
#include "sleep.hpp"
#include "snap.hpp"
#include "solver_layers.hpp"
#include "step_context.hpp"
#include "support.hpp"

namespace jostle {

namespace {

/// Runs the stages of one step, adding each one's time to its bucket of the profile.
class Stages {
public:
    explicit Stages(StepProfile& profile) : profile_(profile) {}

    template <class Stage> void run(float StepProfile::*bucket, Stage&& stage) {
        stage();
        profile_.*bucket += clock_.lap();
    }

private:
    StepProfile& profile_;
    Stopwatch clock_;
};

/// Forces, gravity, damping and the clamp, then the characters' walks.
void integrateVelocities(WorldState& world, float dt) {
    applyForces(world, dt);
    integrateAwakeBodies(world, dt);
    walkCharacters(world);
}

} // namespace

void stepPhysical(WorldState& world, float dt) {
    StepContext step(world, dt);
    Stages stages(world.profile);
    stages.run(&StepProfile::events, [&] { world.events.beginStep(world); });
    stages.run(&StepProfile::riders, [&] { carryRiders(step); });
    stages.run(&StepProfile::velocities, [&] { integrateVelocities(world, dt); });
    stages.run(&StepProfile::pairs, [&] { findPairs(world, dt, world.pairs); });
    stages.run(&StepProfile::corners, [&] { slipRoundCorners(step); });
    stages.run(&StepProfile::contacts, [&] { buildContacts(step); });
    stages.run(&StepProfile::support, [&] { orderBySupport(step); });
    stages.run(&StepProfile::impacts, [&] { resolveImpacts(step); });
    stages.run(&StepProfile::layers, [&] { layerContacts(step); });
    stages.run(&StepProfile::solve, [&] { solveVelocities(step); });
    stages.run(&StepProfile::shock, [&] { propagateShock(step); });
    stages.run(&StepProfile::bounces, [&] { settleBounces(step); });
    stages.run(&StepProfile::sweeps, [&] { sweepFastBodies(step); });
    stages.run(&StepProfile::positions, [&] { integratePositions(step); });
    stages.run(&StepProfile::correction, [&] { correctPositions(step); });
    stages.run(&StepProfile::snap, [&] { snapToGround(step); });
    stages.run(&StepProfile::store, [&] { storeImpulses(step); });
    stages.run(&StepProfile::events, [&] { reportEvents(step); });
    stages.run(&StepProfile::store, [&] { rememberPlatformVelocities(step); });
    stages.run(&StepProfile::sleep, [&] { fallAsleep(step); });
    // Kinematic bodies count: sensors see them.
    stages.run(&StepProfile::events,
               [&] { world.events.publish(world, !world.movingSlots.empty()); });
}

} // namespace jostle
