// Overlap tests between axis-aligned boxes.
#pragma once

#include "jostle/math.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>

namespace jostle {

/// An axis-aligned box: centre and half extents.
struct Box {
    Vec2 centre;
    Vec2 half;
};

/// The tutorial's testRectRect, to the letter: the shortest vector that moves `a` out of
/// `b`, or nothing when they do not overlap. Touching edges are not an overlap. The
/// vector lies along the axis of least penetration; when both axes penetrate equally the
/// tie goes to y. Its signs come from the centre offset a - b, so coincident centres
/// push `a` towards +x or +y.
std::optional<Vec2> shortestSeparation(const Box& a, const Box& b);

inline constexpr float kMinimumSkin = 1e-4f; ///< of the smaller half extent: float noise

/// The gap from |x| to the next float up: how finely coordinates near x are resolved.
inline float ulpOf(float x) {
    const float a = std::abs(x);
    return std::bit_cast<float>(std::bit_cast<std::uint32_t>(a) + 1u) - a;
}

/// The physical model's contact skin of two boxes along one axis, given their half
/// extents on it and the world's slop (a fraction of the smaller half extent): overlap up
/// to this much is touching, not penetrating. Twice the slop, never less than float
/// noise. The solver, its sweeps and the queries all judge touching by it.
inline float contactSkin(float slop, float halfA, float halfB) {
    return std::max(2.0f * slop, kMinimumSkin) * std::min(halfA, halfB);
}

/// Where a moving box first touches another.
struct Hit {
    float time;  ///< fraction of the motion, in [0, 1]
    Vec2 normal; ///< unit, along x or y, pointing from `b` towards the moving box
};

/// Sweeps box `a` along `motion` against the still box `b`: the first time it enters
/// `b`, if it does within the motion. An overlap within `skin` (per axis) at the start
/// is touching, not entering: a box sliding along a floor does not hit the floor, nor
/// the next floor box at their seam. A box that already overlaps `b` deeper than that on
/// both axes is not hit either: it is inside, and the solver's contacts push it out.
std::optional<Hit> sweepBox(const Box& a, Vec2 motion, const Box& b, Vec2 skin);

/// The axis of a contact normal.
enum class Axis { X, Y };

/// The axis along which two boxes touch, for the physical model. `gapX` and `gapY` are
/// the distances between their edges along each axis (negative: they overlap by that
/// much); an overlap within `skinX` / `skinY` is mere touching.
///
/// - Overlapping for real on both axes: the axis of least penetration (a tie goes to y).
/// - Overlapping for real on one axis only: they are side by side along the other.
/// - Touching or apart on both: the axis they touch on (y first), else the larger gap.
///
/// The middle rules are what keep a box sliding along a floor or a wall made of separate
/// boxes from catching on the seams: against the next floor box, the box overlaps only by
/// its resting slop vertically and not at all horizontally, so the contact is a floor
/// contact, not a wall one.
Axis contactAxis(float gapX, float gapY, float skinX, float skinY);

} // namespace jostle
