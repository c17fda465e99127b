// The physical model's step (docs/physical-model.md, docs/architecture.md).
#pragma once

namespace jostle {

struct WorldState;

/// Advances the world by `dt` with every contact of the step solved together.
void stepPhysical(WorldState& world, float dt);

} // namespace jostle
