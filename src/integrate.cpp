// Integration shared by both models, and the edge of the world.
#include "integrate.hpp"

#include "world_state.hpp"

#include <algorithm>
#include <cmath>

namespace jostle {

void integrateVelocity(const WorldDef& def, Body& body, float dt) {
    // The tutorial: d.yv = d.yv + grav, with grav = gravity*dt computed once.
    const Vec2 grav = def.gravity * dt;
    body.velocity += body.gravityScale == 1.0f ? grav : grav * body.gravityScale;
    if (body.damping > 0.0f) {
        const float k = 1.0f + body.damping * dt;
        body.velocity = {body.velocity.x / k, body.velocity.y / k};
    }
    // The hard limit of math.hpp first, per axis: gravity x scale x dt can reach 1e27,
    // whose square (in the length below) would overflow.
    body.velocity = withinRange(body.velocity);
    // clampVec(xv, yv, maxVelocity): scale the vector down to the largest speed.
    if (std::isfinite(def.maxVelocity)) {
        const float d = length(body.velocity);
        if (d > def.maxVelocity) {
            const float n = def.maxVelocity / d;
            body.velocity = body.velocity * n;
        }
    }
}

void applyForces(WorldState& world, float dt) {
    for (const auto& [id, force] : world.forces) {
        if (!world.isCurrent(id))
            continue; // destroyed since
        Body& body = world.slots[id.index];
        body.velocity += force * (body.invMass * dt);
    }
    world.forces.clear();
}

void integrateAwakeBodies(WorldState& world, float dt) {
    // Each body on its own: any split gives the same result.
    world.forEachMover([&](Body& body, Block) {
        if (body.isDynamic() && !body.asleep) {
            integrateVelocity(world.def, body, dt);
            body.dropThroughTime = std::max(0.0f, body.dropThroughTime - dt);
        }
    });
}

bool stopAtTheEdge(Body& body) {
    bool stopped = false;
    auto stop = [&](float& position, float& velocity) {
        if (std::abs(position) > kMaxMagnitude) {
            position = std::copysign(kMaxMagnitude, position);
            velocity = 0.0f;
            stopped = true;
        }
    };
    stop(body.position.x, body.velocity.x);
    stop(body.position.y, body.velocity.y);
    return stopped;
}

void keepInsideTheWorld(WorldState& world) {
    // A flag per block, set on the workers, read after: no two threads write one.
    std::vector<std::uint8_t>& movedAsleep = world.movedAsleepByBlock;
    movedAsleep.assign(world.tasks->blocksOf(std::uint32_t(world.movers().size()), kBodiesPerBlock),
                       0);
    world.forEachMover([&](Body& b, Block block) {
        // Sleeping bodies too: a body can fall asleep in the very step that carried it
        // past the edge (slow enough to rest, with a long enough dt).
        b.velocity = withinRange(b.velocity);
        if (stopAtTheEdge(b) && b.asleep)
            movedAsleep[block.index] = 1;
    });
    for (std::uint8_t moved : movedAsleep)
        if (moved)
            world.restingDirty = true; // it moved within the grid of resting bodies
}

} // namespace jostle
