// Riders of moving platforms (docs/moving-platforms.md): what stands on a kinematic body
// is handed what the body's velocity changed since the last step.
#pragma once

#include <cstdint>
#include <vector>

namespace jostle {

struct StepContext;

struct PlatformScratch {
    std::vector<std::uint8_t> carried; ///< by slot: already given its platform's change
};

/// Stage, first of the step: a body standing on a kinematic body at the end of the last
/// step gets whatever velocity the kinematic body gained since (the game changed it), so
/// riders stay put on a platform that starts, stops or turns, and do not lift off one
/// that starts down. Each rider follows the first platform it stands on, in pair order.
void carryRiders(StepContext& step);

/// Last of the step: each kinematic body remembers the velocity it moved with.
void rememberPlatformVelocities(StepContext& step);

} // namespace jostle
