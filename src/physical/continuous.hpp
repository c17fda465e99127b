// Stage: continuous collision. The solved velocities are handed to the bodies, and a body
// that moves further than its half size in the step, or that the solver sent where its
// contacts did not look, is swept along its motion and stopped where it first meets a
// static or kinematic body (or, for a bullet, any body). What it meets becomes a
// contact of the step.
#pragma once

#include "contact.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace jostle {

struct StepContext;

struct ContinuousScratch {
    std::vector<std::uint8_t> unforeseen; ///< by slot: moves where its contacts did not look
    std::vector<Contact> found;           ///< found by the sweeps, not among the step's
    std::size_t sweepStart = 0;           ///< the first of `found` the current sweep made
};

/// Writes the solver's velocities to the bodies, sweeps the bodies that need it, and adds
/// what the sweeps met to step.contacts (in support order again).
void sweepFastBodies(StepContext& step);

} // namespace jostle
