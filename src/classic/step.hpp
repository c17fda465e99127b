// The classic model's step: the tutorial's update(dt) (docs/classic-model.md).
#pragma once

namespace jostle {

struct WorldState;

/// Advances the world by `dt` as the tutorial does: each dynamic body in creation order
/// moves, then is resolved against the static bodies and the later dynamic ones.
void stepClassic(WorldState& world, float dt);

} // namespace jostle
