// Stage: build contacts. Every pair the broadphase found becomes a contact along one axis
// (or nothing: apart for the whole step, filtered, a one-way platform passed, vetoed by
// the pre-solve callback), warm-started from last step's contact and given its target
// speed (stop, close a speculative gap, or bounce).
#pragma once

#include "contact.hpp"

#include <cstdint>
#include <vector>

namespace jostle {

struct StepContext;
struct Body;

/// What building contacts leaves for later stages.
struct ContactsScratch {
    std::vector<std::uint64_t> vetoed; ///< pairs the pre-solve vetoed this step (sorted keys)
    std::vector<std::uint8_t> made;    ///< what each pair made, when built in parallel
};

/// Fills step.contacts, and step.scratch.sensorPairs with the pairs of a sensor and a
/// body that may overlap it, from step.world.pairs.
void buildContacts(StepContext& step);

/// Whether the pre-solve callback vetoed the contact of these two bodies this step.
bool isVetoed(const StepContext& step, std::uint32_t slotA, std::uint32_t slotB);

/// A contact of `a` and `b`, one of them not a sharp box, along unit `normal` (from b
/// towards a, along an axis or not) where the two touch when (a - b) · normal is `extent`,
/// `size` the smaller reach of the two along it: as the step makes one for such a pair,
/// the rest left to the caller. For the continuous sweep's hits on shapes.
Contact contactAlongShape(const StepContext& step, const Body& a, const Body& b, Vec2 normal,
                          float extent, float size);

} // namespace jostle
