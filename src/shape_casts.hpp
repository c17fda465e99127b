// Moving through shapes, and what is inside them: the sweeps, casts, rays, point and box
// queries of a pair where one body is not a sharp box (shapes.hpp), free of any world.
// geometry.hpp does the same for two boxes, and pairs of boxes keep using it.
//
// Everything is measured as in shapes.hpp: the mover's centre, given relative to the
// obstacle's, against the obstacle's outline (the obstacle grown by the mover's core, with
// the sum of the radii around it). A moving centre is a line through that outline, crossed
// as a ray crosses a convex polygon, and around a rounded corner as a ray crosses a circle.
#pragma once

#include "geometry.hpp"
#include "shapes.hpp"

#include <array>
#include <cstdint>
#include <optional>

namespace jostle {

/// The outline of an obstacle for a mover, and what of it stops the mover.
struct CastOutline {
    Outline outline;
    /// The box faces whose edges stop the mover (shapes.hpp's FaceBit); the slope always
    /// does. A corner between two edges that stop is rounded (with a radius); one beside an
    /// edge that does not is sharp, its stopping edge going on along its line (as touchOf
    /// goes on along it). A segment's faces never stop anything: only its slope does, from
    /// the side it faces. A one-way box's only face is its blocking one.
    std::uint8_t stopping = kAllFaces;
    /// By edge: how deep the mover may be in the outline along that edge's normal and be
    /// touching, not entering (the contact skin, 0 for rays).
    std::array<float, 5> skin{};
};

/// The outline of an obstacle of half extents `half` and shape `shape` for a mover of half
/// extents `moverHalf` and radius `moverRadius` (0: a box), with the faces `stopping` stop
/// and, by edge, the contact skin of the pair: `skinFactor` (twice the slop, at least
/// kMinimumSkin) times the smaller reach of the two along the edge's normal.
CastOutline castOutlineOf(Vec2 moverHalf, float moverRadius, Vec2 half, const Shape& shape,
                          std::uint8_t stopping, float skinFactor);

/// Where a mover meets a shape: geometry.hpp's Hit (its normal from the obstacle towards
/// the mover; its axis kAlongX or kAlongY on a flat face, which lies on the obstacle's box
/// face, kAlongSlope along any other normal: a slope, a rounded corner), and where exactly
/// the two touch.
struct ShapeHit : Hit {
    /// The outline's normal where the mover touches it: `normal`, but for a cast that
    /// touches one edge and goes deeper through the next (as castBox's touch axis).
    Vec2 touching;
    /// The value of dot(offset, touching) at which the two touch along it (offset: the
    /// mover's centre less the obstacle's). An overlap is extent - dot(offset, normal).
    float extent;
};

/// The physical model's sweep (sweepBox for a shape): the mover at `offset` moving by
/// `motion`. The first time it goes deeper into the outline than the skin, through an edge
/// that stops it, within the motion. A mover already that deep is inside, and not hit.
std::optional<ShapeHit> sweepShape(const CastOutline& cast, Vec2 offset, Vec2 motion);

/// The queries' cast (castBox for a shape): the mover runs into the outline when the motion
/// carries it deeper than the skin through an edge that stops it, having not been that deep
/// at the start; the hit is where the two first touch (time 0, axis -1, if they touch
/// already), with the normal of the edge it goes deeper through (around a rounded corner
/// it touches, the corner's where it touches).
std::optional<ShapeHit> castShape(const CastOutline& cast, Vec2 offset, Vec2 motion);

/// The segment from `from` to `from + delta` (relative to the shape's centre) against the
/// closed shape of half extents `half` (castRay for a shape): touching counts, a ray that
/// only leaves it from where it starts does not hit it, and one that starts inside hits at
/// time 0, axis -1, with the normal of the box face it heads for along its main direction.
/// A segment is hit only from the side it faces, through it.
std::optional<ShapeHit> rayShape(Vec2 from, Vec2 delta, Vec2 half, const Shape& shape);

/// Whether the closed shape of half extents `half` holds `point` (relative to its centre).
/// A segment, a line, holds the points on it, within float rounding.
bool shapeHolds(Vec2 half, const Shape& shape, Vec2 point);

/// Whether the shape of half extents `half` and the box of half extents `boxHalf` at
/// `offset` from it share area (touching is not overlapping): a box of size 0 overlaps the
/// shape whose inside holds its centre. A segment shares area with a box the segment
/// crosses.
bool shapeOverlaps(Vec2 half, const Shape& shape, Vec2 offset, Vec2 boxHalf);

} // namespace jostle
