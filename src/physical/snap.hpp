// Stage: snapping to the ground (BodyDef::snapDown). A body that stood on a floor at the
// end of the last step and does not move away from it is moved down onto the floor below,
// so that walking down a slope or over a crest keeps it on the ground.
#pragma once

namespace jostle {

struct StepContext;

/// Moves each awake dynamic body with a snapDown that stood on a floor at the end of the
/// last step, does not move away from that floor, and is now above a floor at most
/// snapDown below it (along gravity), down onto that floor; turns its velocity along it
/// (a character keeps its speed across gravity, another body its speed); and adds the
/// contact if the step has none of the pair, so that the step reports it touching.
void snapToGround(StepContext& step);

} // namespace jostle
