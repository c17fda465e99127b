// Finding the pairs of bodies that may touch during a step.
#pragma once

#include "world_state.hpp"

#include <cstdint>
#include <vector>

namespace jostle {

/// Two bodies that may touch: slot indices, `a` created before `b`.
struct BodyPair {
    std::uint32_t a;
    std::uint32_t b;
};

/// Every pair of live bodies, at least one of them dynamic, whose boxes, each grown by
/// the distance its velocity carries it in `dt` (a margin for speculative contacts),
/// overlap or touch. Pairs come in creation order of `a`, then of `b`, whatever the
/// positions: the same world gives the same list, run after run.
///
/// A sort-and-sweep along x: about n log n for spread-out worlds. (The scale issue
/// replaces it with a broadphase that also copes with huge bodies.)
void findPairs(const WorldState& world, float dt, std::vector<BodyPair>& pairs);

} // namespace jostle
