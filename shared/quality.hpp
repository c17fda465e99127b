// shared/quality.hpp: how well an engine kept a scene, from the bodies' final centres.
//
// One function for every engine, fed with each engine's final positions and the scene's
// own sizes, so the figures compare.
#pragma once

#include "jostle/scene.hpp"

#include <optional>
#include <span>

namespace jostle::shared {

struct Quality {
    /// How far the top box of a pyramid moved from where it started (the largest such
    /// distance in a scene of many pyramids); empty for scenes without a pyramid.
    std::optional<float> topDrift;
    /// The deepest overlap between two bodies, at least one of them dynamic: the smaller
    /// of the overlaps along x and y, so 0 when no two bodies overlap.
    float maxPenetration = 0.0f;
    /// Dynamic bodies whose centre ended outside the scene's bounds (or is not finite).
    int escaped = 0;
};

/// The bodies whose drift is reported: id "top", or "top." followed by anything.
bool isTopBody(const SceneBody& body);

/// The box around every body of the scene at the start, widened on each side by 5% of
/// its larger side plus 1 unit: a dynamic body outside it has left the scene (fallen off
/// the ground, out of a container, through a wall).
struct Bounds {
    Vec2 min;
    Vec2 max;
    bool contains(Vec2 p) const {
        return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y;
    }
};
Bounds sceneBounds(const Scene& scene);

/// The deepest overlap among `positions` (one per scene body, scene order). A uniform grid
/// with cells of twice the largest dynamic half extent finds the pairs, so 100,000 bodies
/// take milliseconds.
float maxPenetration(const Scene& scene, std::span<const Vec2> positions);

/// All three figures for `positions` (one per scene body, scene order).
Quality measureQuality(const Scene& scene, std::span<const Vec2> positions);

} // namespace jostle::shared
