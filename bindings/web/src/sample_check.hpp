// A sample run without a window and hashed bit for bit: the page's check (?check) and the
// native jostle-web-sample-hashes print the same numbers when a sample is the same scene
// in the browser as natively (the keys it plays are fixed here).
#pragma once

#include "sample.hpp"

#include <cstdint>

namespace jostle::web {

/// The keys the check holds at `step`: right for the first second, a jump at half a
/// second, then left; what a player does, so that the steered samples move.
demo::Controls checkControls(int step);

/// Resets `sample` and runs it `steps` steps of 1/60 s with checkControls; FNV-1a over
/// the bits of every body's position and velocity, in every pane, every tenth step.
std::uint64_t runSampleCheck(demo::Sample& sample, int steps);

/// The steps each sample runs in the check: four seconds.
inline constexpr int kCheckSteps = 240;

} // namespace jostle::web
