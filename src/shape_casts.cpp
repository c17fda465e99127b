// Moving through shapes, and what is inside them (shape_casts.hpp states the rules).
#include "shape_casts.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace jostle {

namespace {

const Outline::Edge& edgeOf(const Outline& o, int k) {
    return o.edges[std::size_t(k)];
}

float skinOf(const CastOutline& cast, int k) {
    return cast.skin[std::size_t(k)];
}

/// Whether edge `k` of the outline stops the mover.
bool stops(const CastOutline& cast, int k) {
    const std::uint8_t face = edgeOf(cast.outline, k).face;
    return face == kFaceSlope || (cast.stopping & face) != 0;
}

/// The times `t` at which the line from `start` along `motion` is `radius` away from the
/// origin (a circle around a corner, the start given relative to it), if it comes that
/// close: first <= second.
bool throughCircle(Vec2 start, Vec2 motion, float radius, float& first, float& second) {
    const float a = dot(motion, motion);
    const float b = dot(start, motion);
    const float c = dot(start, start) - radius * radius;
    const float discriminant = b * b - a * c;
    if (!(discriminant >= 0.0f) || !(a > 0.0f))
        return false;
    // The root that does not subtract nearly equal numbers, and the other from it.
    const float q = -(b + std::copysign(std::sqrt(discriminant), b));
    if (q == 0.0f) {
        first = second = 0.0f;
        return true;
    }
    const float r1 = q / a, r2 = c / q;
    first = std::min(r1, r2);
    second = std::max(r1, r2);
    return true;
}

/// A line through an outline: when it is inside, and where it comes in.
struct OutlineCrossing {
    float enter; ///< may be < 0: the line was inside before the start
    float leave;
    int edge;     ///< the edge it comes in through
    bool rounded; ///< around the rounded corner `corner`, not along the edge
    Vec2 corner;
    Vec2 normal; ///< of the outline where it comes in, outward
};

/// Whether the point `p`, on the line of edge `k` (grown), lies beyond one of the edge's
/// ends where the corner is rounded: both edges there stop the mover and keep a positive
/// radius after their skins. Gives the corner and its radius: the larger of the two
/// edges', so that the circle holds the ends of both edges' grown lines (a line that
/// misses it misses the outline there).
bool roundedCornerAt(const CastOutline& cast, bool skinned, int k, Vec2 p, Vec2& corner,
                     float& radius) {
    const Outline& o = cast.outline;
    const Outline::Edge& e = edgeOf(o, k);
    const Vec2 along = e.to - e.from;
    const float t = dot(p - e.from, along);
    const float lengthSquared = dot(along, along);
    if (lengthSquared > 0.0f && t >= 0.0f && t <= lengthSquared)
        return false;
    const bool atFrom = lengthSquared == 0.0f || t < 0.0f;
    const int next = atFrom ? (k + o.count - 1) % o.count : (k + 1) % o.count;
    if (!stops(cast, k) || !stops(cast, next))
        return false;
    corner = atFrom ? e.from : e.to;
    const float thin = skinned ? std::min(skinOf(cast, k), skinOf(cast, next)) : 0.0f;
    const float thick = skinned ? std::max(skinOf(cast, k), skinOf(cast, next)) : 0.0f;
    radius = o.radius - thin;
    return o.radius - thick > 0.0f;
}

/// The line from `start` along `motion` (t any real) against the outline, grown by its
/// radius and, if `skinned`, shrunk by each edge's skin: the closed region's stretch of
/// the line, or nothing if the line misses it (by more than `slack`, in fractions of the
/// motion). The polygon first (Cyrus-Beck: each edge a half-plane, grown by the radius),
/// then, where the line comes in or goes out past the end of an edge at a rounded corner,
/// the circle around that corner: a line that enters the grown polygon there and misses
/// the circle misses the region.
std::optional<OutlineCrossing> crossOutline(const CastOutline& cast, bool skinned, Vec2 start,
                                            Vec2 motion, float slack = 0.0f) {
    const Outline& o = cast.outline;
    float enter = -kInfinity, leave = kInfinity;
    int in = -1, out = -1;
    for (int k = 0; k < o.count; ++k) {
        const Outline::Edge& e = edgeOf(o, k);
        const float bound = e.offset + o.radius - (skinned ? skinOf(cast, k) : 0.0f);
        const float toward = dot(motion, e.normal);
        const float outside = dot(start, e.normal) - bound;
        if (toward == 0.0f) {
            if (outside > 0.0f)
                return std::nullopt;
            continue;
        }
        const float t = -outside / toward;
        if (toward < 0.0f) {
            // Into a corner exactly: the face nearer y, as for boxes.
            if (in < 0 || t > enter ||
                (t == enter && std::abs(e.normal.y) > std::abs(edgeOf(o, in).normal.y))) {
                enter = t;
                in = k;
            }
        } else if (out < 0 || t < leave) {
            leave = t;
            out = k;
        }
    }
    auto misses = [&](float from, float to) {
        return from > to + slack * std::max(std::abs(from), std::abs(to));
    };
    if (in < 0 || out < 0 || misses(enter, leave))
        return std::nullopt;
    OutlineCrossing crossing{enter, leave, in, false, {}, edgeOf(o, in).normal};
    Vec2 corner;
    float radius = 0.0f, first = 0.0f, second = 0.0f;
    if (roundedCornerAt(cast, skinned, in, start + motion * enter, corner, radius)) {
        if (!throughCircle(start - corner, motion, radius, first, second))
            return std::nullopt;
        // The circle may reach past the other edge's grown line: in where both hold.
        if (first >= enter) {
            crossing.enter = first;
            crossing.rounded = true;
            crossing.corner = corner;
            const Vec2 outward = start + motion * first - corner;
            const float distance = length(outward);
            if (distance > 0.0f)
                crossing.normal = outward * (1.0f / distance);
        }
    }
    if (roundedCornerAt(cast, skinned, out, start + motion * leave, corner, radius)) {
        if (!throughCircle(start - corner, motion, radius, first, second))
            return std::nullopt;
        crossing.leave = std::min(leave, second);
    }
    if (misses(crossing.enter, crossing.leave))
        return std::nullopt;
    return crossing;
}

/// The value of dot(offset, normal) at which the mover touches the outline where the
/// crossing comes in (without skin).
float touchingExtent(const CastOutline& cast, const OutlineCrossing& crossing) {
    const Outline& o = cast.outline;
    if (crossing.rounded)
        return dot(crossing.corner, crossing.normal) + o.radius;
    return edgeOf(o, crossing.edge).offset + o.radius;
}

/// ShapeHit::axis of a crossing met at a time > 0.
Axis axisOf(const OutlineCrossing& crossing) {
    const Vec2 n = crossing.normal;
    if (crossing.rounded || (n.x != 0.0f && n.y != 0.0f))
        return kAlongSlope;
    return n.x != 0.0f ? kAlongX : kAlongY;
}

ShapeHit hitOf(const CastOutline& cast, const OutlineCrossing& crossing, float time) {
    return {
        {time, crossing.normal, axisOf(crossing)}, crossing.normal, touchingExtent(cast, crossing)};
}

/// The largest separation of `p` from the outline's edges (without its radius): > 0
/// outside the polygon, <= 0 inside it.
float largestSeparation(const Outline& o, Vec2 p) {
    float largest = -kInfinity;
    for (int k = 0; k < o.count; ++k)
        largest = std::max(largest, dot(p, edgeOf(o, k).normal) - edgeOf(o, k).offset);
    return largest;
}

/// How far `p` lies from the outline's polygon (without its radius), 0 inside it.
float distanceFrom(const Outline& o, Vec2 p) {
    if (largestSeparation(o, p) <= 0.0f)
        return 0.0f;
    float nearest = kInfinity;
    for (int k = 0; k < o.count; ++k) {
        const Outline::Edge& e = edgeOf(o, k);
        const Vec2 along = e.to - e.from;
        const float lengthSquared = dot(along, along);
        const float t = lengthSquared > 0.0f
                            ? std::clamp(dot(p - e.from, along) / lengthSquared, 0.0f, 1.0f)
                            : 0.0f;
        nearest = std::min(nearest, length(p - (e.from + along * t)));
    }
    return nearest;
}

/// The sloped edge of a ramp's or segment's outline.
const Outline::Edge& slopedEdge(const Outline& o) {
    for (int k = 0; k < o.count; ++k)
        if (edgeOf(o, k).face == kFaceSlope)
            return edgeOf(o, k);
    return o.edges[0]; // not reached: only asked of ramps and segments
}

} // namespace

CastOutline castOutlineOf(Vec2 moverHalf, float moverRadius, Vec2 half, const Shape& shape,
                          std::uint8_t stopping, float skinFactor) {
    CastOutline cast;
    cast.outline = outlineOf(moverHalf - Vec2{moverRadius, moverRadius}, moverRadius, half, shape);
    cast.stopping = shape.kind() == ShapeKind::Segment ? std::uint8_t{0} : stopping;
    const Shape mover{moverRadius};
    for (std::size_t k = 0; k < std::size_t(cast.outline.count); ++k) {
        const Vec2 n = cast.outline.edges[k].normal;
        cast.skin[k] = skinFactor * std::min(reachOf(moverHalf, mover, n), reachOf(half, shape, n));
    }
    return cast;
}

std::optional<ShapeHit> sweepShape(const CastOutline& cast, Vec2 offset, Vec2 motion) {
    const std::optional<OutlineCrossing> deep = crossOutline(cast, true, offset, motion);
    if (!deep || !(deep->enter < deep->leave) || deep->enter < 0.0f || deep->enter > 1.0f ||
        !stops(cast, deep->edge))
        return std::nullopt;
    return hitOf(cast, *deep, deep->enter);
}

std::optional<ShapeHit> castShape(const CastOutline& cast, Vec2 offset, Vec2 motion) {
    if (motion.x == 0.0f && motion.y == 0.0f)
        return std::nullopt;
    // Deeper than the skin (the outline shrunk by it), and touching (the outline as it is).
    const std::optional<OutlineCrossing> deep = crossOutline(cast, true, offset, motion);
    const std::optional<OutlineCrossing> touch = crossOutline(cast, false, offset, motion);
    if (!deep || !touch)
        return std::nullopt;
    // Never deeper than the skin; or already that deep at the start (inside, free to
    // leave); or in through an edge that lets it pass.
    if (!(deep->enter < deep->leave) || deep->enter < 0.0f || !stops(cast, deep->edge))
        return std::nullopt;
    // Touching comes at or before going deeper, and may be before the start (overlapping
    // within the skin: moving in stops at once).
    const float time = touch->enter;
    if (time > 1.0f)
        return std::nullopt;
    if (time <= 0.0f)
        return ShapeHit{
            {0.0f, deep->normal, kFromInside}, deep->normal, touchingExtent(cast, *deep)};
    // The normal of the edge it goes into; around a rounded corner, where it touches it.
    ShapeHit hit = hitOf(cast, *touch, time);
    if (!(deep->rounded && touch->rounded && deep->corner == touch->corner))
        hit.normal = deep->normal;
    return hit;
}

std::optional<ShapeHit> rayShape(Vec2 from, Vec2 delta, Vec2 half, const Shape& shape) {
    if (delta.x == 0.0f && delta.y == 0.0f)
        return std::nullopt; // no direction: nothing to meet
    const CastOutline cast = castOutlineOf({}, 0.0f, half, shape, kAllFaces, 0.0f);
    // A ray that grazes a corner touches it: rounding must not make it miss (a few float
    // steps of the fractions).
    const std::optional<OutlineCrossing> crossing = crossOutline(cast, false, from, delta, 1e-6f);
    // leave <= 0: the ray starts on the shape's far side, heading away.
    if (!crossing || crossing->enter > 1.0f || crossing->leave <= 0.0f)
        return std::nullopt;
    if (crossing->enter >= 0.0f) {
        if (!stops(cast, crossing->edge))
            return std::nullopt; // a segment, from behind or from its end
        return hitOf(cast, *crossing, crossing->enter);
    }
    if (shape.kind() == ShapeKind::Segment)
        return std::nullopt; // behind it from the start
    // Inside from the start: the face the ray heads for along its main direction.
    const int heading = std::abs(delta.y) >= std::abs(delta.x) ? 1 : 0;
    Vec2 normal{0.0f, 0.0f};
    normal[heading] = delta[heading] > 0.0f ? -1.0f : 1.0f;
    return ShapeHit{{0.0f, normal, kFromInside}, normal, 0.0f};
}

bool shapeHolds(Vec2 half, const Shape& shape, Vec2 point) {
    const Outline o = outlineOf({}, 0.0f, half, shape);
    if (shape.kind() == ShapeKind::Segment) {
        // On the slope's line, within rounding, and between its ends.
        const Outline::Edge& slope = slopedEdge(o);
        const float onLine = dot(point, slope.normal) - slope.offset;
        const float rounding =
            4.0f * ulpOf(std::max({std::abs(point.x), std::abs(point.y), half.x, half.y}));
        return std::abs(onLine) <= rounding && largestSeparation(o, point) <= rounding;
    }
    if (o.radius > 0.0f)
        return distanceFrom(o, point) <= o.radius;
    return largestSeparation(o, point) <= 0.0f;
}

bool shapeOverlaps(Vec2 half, const Shape& shape, Vec2 offset, Vec2 boxHalf) {
    const Outline o = outlineOf(boxHalf, 0.0f, half, shape);
    if (shape.kind() == ShapeKind::Segment) {
        // Inside the ramp's outline, and in front of the line the box's far corner
        // touches: the box holds points on both sides of the segment.
        const Outline::Edge& slope = slopedEdge(o);
        const float reach =
            std::abs(slope.normal.x) * boxHalf.x + std::abs(slope.normal.y) * boxHalf.y;
        return largestSeparation(o, offset) < 0.0f &&
               dot(offset, slope.normal) - slope.offset > -2.0f * reach;
    }
    if (o.radius > 0.0f)
        return distanceFrom(o, offset) < o.radius;
    return largestSeparation(o, offset) < 0.0f;
}

} // namespace jostle
