// Shapes beyond the sharp box: rounded boxes (capsules and circles are rounded boxes) and
// ramps (a box cut along its diagonal), with the one-sided segment, a ramp's sloped face
// alone. The geometry of a pair with one of them, free of any world: the outline the
// moving body's centre must stay out of, and where it touches it.
//
// Every shape sits in its body's box (centre ± half extents). A rounded box is its core,
// the box shrunk by the radius, grown by a disc of that radius: two rounded boxes touch
// where their cores are the sum of the radii apart. A ramp keeps the right triangle whose
// long side faces BodyDef::slope.
#pragma once

#include "jostle/math.hpp"

#include <array>
#include <cstdint>
#include <optional>

namespace jostle {

/// What a body is, as the narrowphase tells them apart. Kept in Body (one byte in its hot
/// half); the numbers of the shape are in WorldState::shapes, read only for non-boxes.
enum class ShapeKind : std::uint8_t { Box, Round, Ramp, Segment };

/// A body's shape beyond its box: BodyDef::radius, slope and segment.
struct Shape {
    float radius = 0.0f;
    Vec2 slope{};
    bool segment = false;

    ShapeKind kind() const {
        if (slope != Vec2{})
            return segment ? ShapeKind::Segment : ShapeKind::Ramp;
        return radius > 0.0f ? ShapeKind::Round : ShapeKind::Box;
    }
};

/// The faces of a body's box, as bits: which ones may push (see Outline).
enum FaceBit : std::uint8_t {
    kFaceMinusX = 1,
    kFacePlusX = 2,
    kFaceMinusY = 4,
    kFacePlusY = 8,
    kAllFaces = 15,
    kFaceSlope = 16, ///< a ramp's sloped face (an outline's edge from it)
};

/// The face bit of the box face whose outward normal is `sign` along `axis`.
inline std::uint8_t faceBit(int axis, float sign) {
    return std::uint8_t(1u << (2 * axis + (sign > 0.0f ? 1 : 0)));
}

/// `v` scaled to length 1 (v must not be zero).
inline Vec2 normalize(Vec2 v) {
    return v * (1.0f / length(v));
}

/// The sloped face's outward normal of a ramp of half extents `half` facing `slope`.
inline Vec2 slopeNormal(Vec2 half, Vec2 slope) {
    return normalize(Vec2{slope.x * half.y, slope.y * half.x});
}

/// How far a body of half extents `half` and shape `shape` reaches from its centre along
/// unit `normal`, for the slop and skin of a pair: a rounded box (a sharp one has radius
/// 0) its core's reach plus its radius; a ramp or segment its smaller half extent.
float reachOf(Vec2 half, const Shape& shape, Vec2 normal);

/// Where two bodies touch along unit `normal` (from b towards a), either of them any
/// shape: along the normal, halfway between the parts of the two that face each other;
/// across it, the middle of the stretch those parts share, as geometry.hpp's touchPoint
/// has it for two sharp boxes. A face facing a face (a box against a ramp's leg, a
/// capsule's side against a wall) shares a stretch; a corner or a curve touches at a
/// point (a box's corner on a slope, a circle at its centre less its radius times the
/// normal). `offset` is a's centre less b's; the point is returned relative to b's centre.
Vec2 touchPointOf(Vec2 offset, Vec2 halfA, const Shape& shapeA, Vec2 halfB, const Shape& shapeB,
                  Vec2 normal);

/// The region a body's centre must stay out of to stay clear of an obstacle: the obstacle
/// grown by the body's core (Minkowski sum), a convex polygon of up to five edges, and
/// the sum of the radii around it. Each edge comes from one face of the obstacle's box
/// (a ramp's tips count as the faces they end on) or from its sloped face.
struct Outline {
    struct Edge {
        Vec2 normal;       ///< outward, unit
        float offset;      ///< the edge's line: dot(p, normal) == offset
        Vec2 from, to;     ///< counter-clockwise in a y-up frame
        std::uint8_t face; ///< its box face's bit (kFaceMinusX...), or kFaceSlope
    };
    std::array<Edge, 5> edges;
    int count = 0;
    float radius = 0.0f;
};

/// The outline of an obstacle of half extents `half` and shape `shape` for a body whose
/// core has half extents `core` and whose radius is `radius`.
Outline outlineOf(Vec2 core, float radius, Vec2 half, const Shape& shape);

/// Where a body whose centre is at `offset` from an obstacle's touches the obstacle's
/// outline: the normal (from the obstacle towards the body) and the gap along it (negative:
/// overlap), and the contact's extent, the value of dot(offset, normal) at which the gap is
/// 0 along that normal.
struct Touch {
    Vec2 normal;
    float gap;
    float extent;
    /// Around a corner of the outline: the corner, else nothing.
    std::optional<Vec2> corner;
};

/// A touch around a rounded corner, of a body apart from it, turned to the normal at which
/// the body's path `motion` (relative to the obstacle) first meets the corner: the normal
/// of the impact, not of where the body is now. Nothing if the path misses the corner
/// (it does not meet it in this step). Any other touch is returned as it is.
std::optional<Touch> atImpact(const Touch& touch, Vec2 offset, Vec2 motion, float radius);

/// How the body at `offset` touches `outline`, pushed only by edges whose face is in
/// `pushing` (the sloped face always pushes unless `slopedPushes` is false): the pushing
/// edge it is least deep behind or furthest in front of. Past the end of that edge, where
/// the next edge pushes too, around the corner between them (a rounded body rolls over a
/// crest); where the next edge does not push, along the edge's line (a face covered by
/// the level's next body goes on as that body's face). Nothing if no edge may push.
/// `apart` receives the largest gap along any edge: beyond the skin, the two are apart.
std::optional<Touch> touchOf(const Outline& outline, Vec2 offset, std::uint8_t pushing,
                             bool slopedPushes, float& apart);

} // namespace jostle
