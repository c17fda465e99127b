// Stages: positions from velocities, then position correction. Overlap beyond the slop
// is removed by moving the bodies (the one that holds the other stays; else both move,
// by inverse mass); velocities are left alone, so no energy is added.
#pragma once

namespace jostle {

struct StepContext;

/// Moves every body that was moving when the step began by its velocity.
void integratePositions(StepContext& step);

/// Runs the position passes over the step's contacts and writes the corrected positions
/// to the bodies, counting the move in their separation.
void correctPositions(StepContext& step);

} // namespace jostle
