// Stage: continuous collision. The solved velocities are handed to the bodies, and a body
// that moves further than its half size in the step, or that the solver sent where its
// contacts did not look, is swept along its motion and stopped where it first meets a
// static or kinematic body (or, for a bullet, any body). What it meets becomes a
// contact of the step.
#pragma once

#include "../geometry.hpp"
#include "../tasks.hpp"
#include "contact.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace jostle {

struct StepContext;

/// What a sweep of a body met first.
struct FirstHit {
    Hit hit;
    std::uint32_t slot; ///< the obstacle
    /// A hit on a shape (a pair where one is not a sharp box): the contact's extent along
    /// the normal, and the smaller reach of the two along it (shape_casts.hpp).
    float extent = 0.0f;
    float size = 0.0f;
};

struct ContinuousScratch {
    std::vector<std::uint8_t> unforeseen; ///< by slot: moves where its contacts did not look
    PerBlock<std::uint32_t> toSweep;      ///< slots whose sweep hits something, by block
    std::vector<Contact> found;           ///< found by the sweeps, not among the step's
    std::size_t sweepStart = 0;           ///< the first of `found` the current sweep made
};

/// Adds to scratch.continuous.found a contact for hit `first` of the sweep of `slot` (its
/// normal from the obstacle towards the body), met at `speed`: it holds the body on the
/// obstacle's side when position correction pushes it there from the other side, and
/// reports the touch. Unless a contact of the pair is in the step already.
void addFoundContact(StepContext& step, std::uint32_t slot, const FirstHit& first, float speed);

/// Writes the solver's velocities to the bodies, sweeps the bodies that need it, and adds
/// what the sweeps met to step.contacts (in support order again).
void sweepFastBodies(StepContext& step);

} // namespace jostle
