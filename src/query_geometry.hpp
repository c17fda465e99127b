// The geometry of queries, free of any world: a ray against a box, and a moving box
// against a still one. jostle/query.hpp states the rules; this is where they are decided.
#pragma once

#include "box_grid.hpp"
#include "collide.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace jostle {

/// Where a ray meets a box.
struct RayContact {
    float fraction; ///< along the ray, in [0, 1]
    Vec2 normal;    ///< unit, along x or y, against the ray
    /// The axis whose face the ray enters through (0: x, 1: y); -1 if it starts inside.
    int axis;
};

/// The segment from `from` to `from + delta` against the closed box `box`: touching
/// counts, except for a ray that only leaves the box from where it starts.
inline std::optional<RayContact> rayAgainstBox(Vec2 from, Vec2 delta, const Bounds& box) {
    if (delta.x == 0.0f && delta.y == 0.0f)
        return std::nullopt; // no direction: nothing to meet
    constexpr float kInfinity = std::numeric_limits<float>::infinity();
    const float start[2] = {from.x, from.y};
    const float move[2] = {delta.x, delta.y};
    const float low[2] = {box.min.x, box.min.y};
    const float high[2] = {box.max.x, box.max.y};
    // The slab method: the ray is within the box while it is between the two faces of
    // each axis; it enters the box when it has entered both slabs.
    float enter[2] = {-kInfinity, -kInfinity};
    float leave = kInfinity;
    for (int axis = 0; axis < 2; ++axis) {
        if (move[axis] == 0.0f) {
            // Parallel to this axis's faces: between them all along (on one counts), or never.
            if (start[axis] < low[axis] || start[axis] > high[axis])
                return std::nullopt;
            continue;
        }
        const float toLow = (low[axis] - start[axis]) / move[axis];
        const float toHigh = (high[axis] - start[axis]) / move[axis];
        enter[axis] = std::min(toLow, toHigh);
        leave = std::min(leave, std::max(toLow, toHigh));
    }
    const int axis = enter[1] >= enter[0] ? 1 : 0; // into a corner: the y face
    const float entry = enter[axis];
    // entry == leave is a grazed corner: it counts. leave <= 0: the ray starts on the box's
    // far side, heading away.
    if (entry > leave || entry > 1.0f || leave <= 0.0f)
        return std::nullopt;
    if (entry >= 0.0f) {
        Vec2 normal{0.0f, 0.0f};
        (axis == 0 ? normal.x : normal.y) = move[axis] > 0.0f ? -1.0f : 1.0f;
        return RayContact{entry, normal, axis};
    }
    // Inside from the start: the face the ray heads for along its main direction.
    const bool alongY = std::abs(delta.y) >= std::abs(delta.x);
    const Vec2 normal = alongY ? Vec2{0.0f, delta.y > 0.0f ? -1.0f : 1.0f}
                               : Vec2{delta.x > 0.0f ? -1.0f : 1.0f, 0.0f};
    return RayContact{0.0f, normal, -1};
}

/// Where a moving box first touches a still one.
struct CastContact {
    float time;  ///< fraction of the motion, in [0, 1]
    Vec2 normal; ///< unit, along x or y, from the still box towards the moving one
    /// The axis along which the boxes come into contact at `time` (0: x, 1: y), where the
    /// moving box's centre lies exactly at its half extent from the other's face; -1 when
    /// they already touch at the start.
    int touchAxis;
};

/// Sweeps `moving` along `motion` against `still`: the time it first touches `still`, if it
/// runs into it within the motion. It runs into it when the motion carries it deeper than
/// `skin` into `still` on both axes at once, having not been that deep at the start.
/// Touching, or overlapping within the skin, while moving along a face is not running
/// into it: a box slides over a floor and across the seams of a floor of separate boxes.
inline std::optional<CastContact> castBoxAgainst(const Box& moving, Vec2 motion, const Box& still,
                                                 Vec2 skin) {
    constexpr float kInfinity = std::numeric_limits<float>::infinity();
    // The centre of `moving` as a ray against `still` grown by moving's half extents
    // (their Minkowski sum), once as it is (where they touch) and once shrunk by the skin
    // (where they penetrate).
    const float start[2] = {moving.centre.x - still.centre.x, moving.centre.y - still.centre.y};
    const float move[2] = {motion.x, motion.y};
    const float reach[2] = {moving.half.x + still.half.x, moving.half.y + still.half.y};
    const float skins[2] = {skin.x, skin.y};
    float touch[2] = {-kInfinity, -kInfinity};     // entering the grown box, per axis
    float penetrate[2] = {-kInfinity, -kInfinity}; // entering the shrunk box, per axis
    float leave = kInfinity;                       // leaving the shrunk box
    bool moves = false;
    for (int axis = 0; axis < 2; ++axis) {
        const float deep = reach[axis] - skins[axis];
        if (deep <= 0.0f)
            return std::nullopt; // cannot happen with half extents > 0; a guard
        if (move[axis] == 0.0f) {
            // Parallel: deeper than the skin all along, or never.
            if (!(std::abs(start[axis]) < deep))
                return std::nullopt;
            continue;
        }
        moves = true;
        const float towards = move[axis] > 0.0f ? 1.0f : -1.0f;
        touch[axis] = (-towards * reach[axis] - start[axis]) / move[axis];
        penetrate[axis] = (-towards * deep - start[axis]) / move[axis];
        leave = std::min(leave, (towards * deep - start[axis]) / move[axis]);
    }
    if (!moves)
        return std::nullopt;
    const int axis = penetrate[1] >= penetrate[0] ? 1 : 0; // into a corner: the y face
    const float enter = penetrate[axis];
    // Never deeper than the skin on both axes at once; or already that deep at the start
    // (inside, free to leave).
    if (!(enter < leave) || enter < 0.0f)
        return std::nullopt;
    // They touch when both axes touch. That is at or before the penetration, and may be
    // before the start (overlapping within the skin: moving in stops at once).
    const int touchAxis = touch[1] >= touch[0] ? 1 : 0;
    const float time = touch[touchAxis];
    if (time > 1.0f)
        return std::nullopt;
    Vec2 normal{0.0f, 0.0f};
    (axis == 0 ? normal.x : normal.y) = move[axis] > 0.0f ? -1.0f : 1.0f;
    if (time <= 0.0f)
        return CastContact{0.0f, normal, -1};
    return CastContact{time, normal, touchAxis};
}

} // namespace jostle
