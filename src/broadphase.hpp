// The world's broadphase: which bodies may touch. Two BoxGrids: one of the bodies at rest
// (static and sleeping), rebuilt only when one of them changes, which both models and the
// queries use, and one of the moving bodies, rebuilt every physical step
// (docs/broadphase.md).
#pragma once

#include <cstdint>
#include <vector>

namespace jostle {

struct WorldState;

/// Two bodies that may touch: slot indices, `a` created before `b`.
struct BodyPair {
    std::uint32_t a;
    std::uint32_t b;
};

/// Rebuilds the world's resting grid (static and sleeping bodies) if one of them changed.
void refreshRestingGrid(WorldState& world);

/// Every pair of live bodies, at least one of them dynamic and awake (or a sensor and an
/// awake dynamic or kinematic body), whose boxes, each grown by the distance its velocity
/// carries it in `dt`, overlap or touch; `a` is the one created first. Sleeping bodies touched by
/// awake ones are woken first, so they take part. The order is fixed: the same world gives the same
/// list.
void findPairs(WorldState& world, float dt, std::vector<BodyPair>& pairs);

} // namespace jostle
