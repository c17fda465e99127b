// The geometry of boxes, free of any world: one box type, the tutorial's shortest
// separation, the axis a contact lies along, and one primitive for everything that moves
// through a box (the solvers' sweeps, box casts, move-and-slide and rays).
//
// A body's shape is a centre and half extents; a pair of bodies is measured by the
// offset between their centres and the sum of their half extents (the tutorial's dx, dy
// and shw, shh): the moving one's centre against the other grown by its half extents.
#pragma once

#include "jostle/math.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

namespace jostle {

/// Where a sweep that never meets anything enters or leaves: at no time.
inline constexpr float kInfinity = std::numeric_limits<float>::infinity();

/// An axis-aligned box given by its corners, min <= max: a body's box, a region a query
/// or a sweep looks at, a cell's contents.
struct Box {
    Vec2 min;
    Vec2 max;
};

/// The box of a body: `centre` ± `half`.
inline Box boxAround(Vec2 centre, Vec2 half) {
    return {centre - half, centre + half};
}

/// The region a box of half extents `half` covers moving from `centre` by `motion`.
inline Box sweptBox(Vec2 centre, Vec2 half, Vec2 motion) {
    const Vec2 to = centre + motion;
    return {{std::min(centre.x, to.x) - half.x, std::min(centre.y, to.y) - half.y},
            {std::max(centre.x, to.x) + half.x, std::max(centre.y, to.y) + half.y}};
}

/// True when the two boxes overlap or touch. All four compared, without a branch between
/// them: the broadphase counts on it (BoxGrid gathers a run's touching boxes branch-free).
inline bool touches(const Box& a, const Box& b) {
    return (a.min.x <= b.max.x) & (b.min.x <= a.max.x) & (a.min.y <= b.max.y) &
           (b.min.y <= a.max.y);
}

/// True when the two boxes share area: touching edge to edge is not overlapping.
inline bool overlaps(const Box& a, const Box& b) {
    return a.min.x < b.max.x && b.min.x < a.max.x && a.min.y < b.max.y && b.min.y < a.max.y;
}

/// The tutorial's testRectRect, to the letter: the shortest vector that moves box a out
/// of box b, or nothing when they do not overlap; `offset` is a's centre less b's, `reach`
/// the sum of their half extents. Touching edges are not an overlap. The vector lies along
/// the axis of least penetration; when both axes penetrate equally the tie goes to y. Its
/// signs come from the offset, so coincident centres push `a` towards +x or +y.
std::optional<Vec2> shortestSeparation(Vec2 offset, Vec2 reach);

/// Where two boxes touch along `normal` (unit, along x or y, from b towards a): halfway
/// between the faces they turn to each other, at the middle of their overlap along them.
inline Vec2 touchPoint(const Box& a, const Box& b, Vec2 normal) {
    const int axis = normal.x != 0.0f ? 0 : 1;
    const int along = 1 - axis;
    const bool aAfter = normal[axis] > 0.0f; // a lies on the + side of b
    const float aFace = aAfter ? a.min[axis] : a.max[axis];
    const float bFace = aAfter ? b.max[axis] : b.min[axis];
    Vec2 point;
    point[axis] = 0.5f * (aFace + bFace);
    point[along] =
        0.5f * (std::max(a.min[along], b.min[along]) + std::min(a.max[along], b.max[along]));
    return point;
}

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

/// Which way a contact, a hit or a cast points, the one vocabulary of every stage and
/// query: along x or along y (a vector's index 0 or 1), or along a slope or a curve (a
/// normal at an angle); and, for a hit, from inside (touching or overlapping from the
/// start, no face crossed).
enum Axis : std::int8_t { kFromInside = -1, kAlongX = 0, kAlongY = 1, kAlongSlope = 2 };

/// The axis along which two boxes touch, for the physical model. `gapX` and `gapY` are
/// the distances between their edges along each axis (negative: they overlap by that
/// much); an overlap within `skinX` / `skinY` is mere touching.
///
/// - Overlapping for real on both axes: the axis of least penetration (a tie goes to y).
/// - Overlapping for real on one axis only: they are side by side along the other.
/// - Touching or apart on both: the axis they touch on (y first), else the larger gap.
///
/// The middle rules keep a box sliding along a floor or a wall made of separate boxes from
/// catching on the seams (docs/physical-model.md, "Contacts").
Axis contactAxis(float gapX, float gapY, float skinX, float skinY);

// --- Moving through a box ------------------------------------------------------------------

/// Where something moving meets a box.
struct Hit {
    float time;  ///< fraction of the motion, in [0, 1]
    Vec2 normal; ///< unit, along x or y: the face met, pointing back at the mover
    /// The axis of the face the mover lies on exactly at `time` (kAlongX, kAlongY; a shape's
    /// hit may be kAlongSlope); kFromInside when it touches the box, or is inside it, from
    /// the start.
    Axis axis;
};

/// The solvers' sweep: box a moving by `motion` against still box b (`offset`, `reach`:
/// see the top of the file). The first time a goes deeper into b than `skin` along both
/// axes, within the motion. An overlap within the skin at the start is touching, not
/// entering: a box sliding along a floor does not hit the floor, nor the next floor box at
/// their seam. A box already deeper than that on both axes is not hit either: it is
/// inside, and the contacts push it out. Into a corner exactly: the x face.
std::optional<Hit> sweepBox(Vec2 offset, Vec2 reach, Vec2 motion, Vec2 skin);

/// The queries' cast (boxCast, moveAndSlide): box a moving by `motion` against box b. It
/// runs into b when the motion carries it deeper than `skin` on both axes at once, having
/// not been that deep at the start; then the hit is where the two first touch (time 0 and
/// axis -1 if they touch already). Moving along a face it touches is not running into it.
/// Into a corner exactly: the y face.
std::optional<Hit> castBox(Vec2 offset, Vec2 reach, Vec2 motion, Vec2 skin);

/// The segment from `from` to `from + delta` against the closed box `box`: touching
/// counts (a grazed corner too), except for a ray that only leaves the box from where it
/// starts. A ray that starts inside hits at time 0, axis -1, with the normal of the face it
/// heads for along its main direction. Into a corner exactly: the y face.
std::optional<Hit> castRay(Vec2 from, Vec2 delta, const Box& box);

} // namespace jostle
