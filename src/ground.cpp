// What a body stands on (ground.hpp).
#include "ground.hpp"

#include "world_state.hpp"

namespace jostle {

GroundRecord groundOf(const WorldState& world, BodyId id) {
    GroundRecord ground;
    float hardest = 0.0f;
    world.forEachContactOf(id, [&](BodyId other, Vec2 push, const TouchRecord& r) {
        if (surfaceOf(push, world.events.down, world.slots[id.index].floorCos) != kFloor ||
            (!ground.body.isNull() && !(r.impulse > hardest)))
            return;
        ground = {other, push};
        hardest = r.impulse;
    });
    return ground;
}

} // namespace jostle
