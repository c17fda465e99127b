// The outline of an obstacle for a moving body, and where the body touches it.
#include "shapes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace jostle {

namespace {

/// The corners of a box of half extents h, counter-clockwise in a y-up frame, and the
/// face of the edge that starts at each.
constexpr Vec2 kCornerSigns[4] = {{-1.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f}, {-1.0f, 1.0f}};
constexpr std::uint8_t kEdgeFaces[4] = {kFaceMinusY, kFacePlusX, kFacePlusY, kFaceMinusX};
constexpr Vec2 kEdgeNormals[4] = {{0.0f, -1.0f}, {1.0f, 0.0f}, {0.0f, 1.0f}, {-1.0f, 0.0f}};

Vec2 scaled(Vec2 signs, Vec2 h) {
    return {signs.x * h.x, signs.y * h.y};
}

/// Vertices this much closer along a direction than the furthest (as a fraction of the
/// shape's size) still face it: float noise in a slope's normal, not a tilt.
constexpr float kSameReach = 1e-5f;

/// The part of a shape (half extents `half`) that faces unit `direction`, seen as a polygon
/// grown by a radius (a rounded box's core and radius, a ramp's triangle, a segment's two
/// ends): the polygon's vertices furthest along `direction`.
struct FacingPart {
    float reach; ///< along `direction` from the shape's centre, the radius included
    float low;   ///< the extent of the facing vertices along `across`
    float high;
    Vec2 vertex; ///< one of them, from the shape's centre
    float radius;

    /// A corner or a curve, not a face: the facing vertices are one (a circle's core
    /// has four, all in one place).
    bool isPoint() const { return low == high; }
};

FacingPart facingPart(Vec2 half, const Shape& shape, Vec2 direction, Vec2 across) {
    const ShapeKind kind = shape.kind();
    const float radius = kind == ShapeKind::Round ? shape.radius : 0.0f;
    const Vec2 core = half - Vec2{radius, radius};
    const bool cut = kind == ShapeKind::Ramp || kind == ShapeKind::Segment;
    Vec2 vertices[4];
    int n = 0;
    for (const Vec2& signs : kCornerSigns) {
        const bool cutOff = cut && signs == shape.slope;
        const bool behindFace = kind == ShapeKind::Segment && signs == -shape.slope;
        if (!cutOff && !behindFace)
            vertices[n++] = scaled(signs, core);
    }
    float furthest = -std::numeric_limits<float>::infinity();
    for (int i = 0; i < n; ++i)
        furthest = std::max(furthest, dot(vertices[i], direction));
    const float tie = kSameReach * (half.x + half.y);
    FacingPart part{furthest + radius, std::numeric_limits<float>::infinity(),
                    -std::numeric_limits<float>::infinity(), Vec2{}, radius};
    for (int i = 0; i < n; ++i) {
        if (dot(vertices[i], direction) < furthest - tie)
            continue;
        part.low = std::min(part.low, dot(vertices[i], across));
        part.high = std::max(part.high, dot(vertices[i], across));
        part.vertex = vertices[i];
    }
    return part;
}

} // namespace

Vec2 touchPointOf(Vec2 offset, Vec2 halfA, const Shape& shapeA, Vec2 halfB, const Shape& shapeB,
                  Vec2 normal) {
    const Vec2 across{-normal.y, normal.x};
    const FacingPart a = facingPart(halfA, shapeA, -normal, across);
    const FacingPart b = facingPart(halfB, shapeB, normal, across);
    if (a.isPoint() && b.isPoint()) {
        // A corner or a curve against a corner or a curve: they touch on the line between
        // the two vertices (a curve's is its core's corner), whichever way the normal found
        // when they met pointed (a circle goes on round a corner after meeting it).
        const Vec2 va = offset + a.vertex;
        const Vec2 between = va - b.vertex;
        const float distance = length(between);
        if (distance > 0.0f) {
            const Vec2 u = between * (1.0f / distance);
            return ((va - u * a.radius) + (b.vertex + u * b.radius)) * 0.5f;
        }
    }
    // Else across the normal, the middle of the stretch the two facing parts share (of
    // the gap between them, should they not overlap); along it, halfway between the two.
    const float aAcross = dot(offset, across);
    const float along = 0.5f * ((dot(offset, normal) - a.reach) + b.reach);
    const float middle =
        0.5f * (std::max(aAcross + a.low, b.low) + std::min(aAcross + a.high, b.high));
    return normal * along + across * middle;
}

float reachOf(Vec2 half, const Shape& shape, Vec2 normal) {
    const ShapeKind kind = shape.kind();
    if (kind == ShapeKind::Ramp || kind == ShapeKind::Segment)
        return std::min(half.x, half.y);
    const float r = shape.radius;
    return std::abs(normal.x) * (half.x - r) + std::abs(normal.y) * (half.y - r) + r;
}

Outline outlineOf(Vec2 core, float radius, Vec2 half, const Shape& shape) {
    Outline o;
    const ShapeKind kind = shape.kind();
    const Vec2 obstacleCore =
        kind == ShapeKind::Round ? half - Vec2{shape.radius, shape.radius} : half;
    o.radius = radius + (kind == ShapeKind::Round ? shape.radius : 0.0f);
    const Vec2 h = core + obstacleCore;
    // The corner a ramp cuts off, or none.
    int cut = -1;
    if (kind == ShapeKind::Ramp || kind == ShapeKind::Segment)
        for (int i = 0; i < 4; ++i)
            if (kCornerSigns[i] == shape.slope)
                cut = i;
    // The vertices, each with the face of the edge that starts at it.
    Vec2 vertices[5];
    std::uint8_t faces[5];
    int n = 0;
    for (int i = 0; i < 4; ++i) {
        if (i != cut) {
            vertices[n] = scaled(kCornerSigns[i], h);
            faces[n++] = kEdgeFaces[i];
            continue;
        }
        // The cut corner becomes the sloped edge between the two faces that met there:
        // the body's core corner sliding along the slope from tip to tip.
        const Vec2 s = shape.slope;
        const Vec2 onX{s.x * h.x, s.y * (core.y - obstacleCore.y)};
        const Vec2 onY{s.x * (core.x - obstacleCore.x), s.y * h.y};
        const bool xFaceFirst = (kEdgeFaces[(i + 3) % 4] & (kFaceMinusX | kFacePlusX)) != 0;
        vertices[n] = xFaceFirst ? onX : onY;
        faces[n++] = kFaceSlope;
        vertices[n] = xFaceFirst ? onY : onX;
        faces[n++] = kEdgeFaces[i];
    }
    const Vec2 slopeNormalHere = cut >= 0 ? slopeNormal(half, shape.slope) : Vec2{};
    for (int k = 0; k < n; ++k) {
        Outline::Edge& e = o.edges[std::size_t(k)];
        e.from = vertices[k];
        e.to = vertices[(k + 1) % n];
        e.face = faces[k];
        if (e.face == kFaceSlope) {
            e.normal = slopeNormalHere;
        } else {
            for (int f = 0; f < 4; ++f)
                if (kEdgeFaces[f] == e.face)
                    e.normal = kEdgeNormals[f];
        }
        e.offset = dot(e.from, e.normal);
    }
    o.count = n;
    return o;
}

std::optional<Touch> touchOf(const Outline& outline, Vec2 offset, std::uint8_t pushing,
                             bool slopedPushes, float& apart) {
    const float radius = outline.radius;
    auto pushes = [&](int k) {
        const std::uint8_t face = outline.edges[std::size_t(k)].face;
        return face == kFaceSlope ? slopedPushes : (pushing & face) != 0;
    };
    apart = -std::numeric_limits<float>::infinity();
    int best = -1;
    float bestSeparation = -std::numeric_limits<float>::infinity();
    for (int k = 0; k < outline.count; ++k) {
        const Outline::Edge& e = outline.edges[std::size_t(k)];
        const float separation = dot(offset, e.normal) - e.offset;
        apart = std::max(apart, separation - radius);
        if (pushes(k) && separation > bestSeparation) {
            best = k;
            bestSeparation = separation;
        }
    }
    if (best < 0)
        return std::nullopt;
    const Outline::Edge& e = outline.edges[std::size_t(best)];
    const Touch alongFace{e.normal, bestSeparation - radius, e.offset + radius, std::nullopt};
    if (!(bestSeparation > 0.0f))
        return alongFace; // inside: out through the pushing edge it is least deep behind
    // In front of the edge: past one of its ends, around the corner if the edge beyond
    // pushes too.
    const Vec2 along = e.to - e.from;
    const float t = dot(offset - e.from, along);
    const float lengthSquared = dot(along, along);
    int next;
    Vec2 corner;
    if (lengthSquared > 0.0f && t < 0.0f) {
        next = (best + outline.count - 1) % outline.count;
        corner = e.from;
    } else if (lengthSquared > 0.0f && t > lengthSquared) {
        next = (best + 1) % outline.count;
        corner = e.to;
    } else if (lengthSquared == 0.0f) {
        next = best; // a point: round it
        corner = e.from;
    } else {
        return alongFace;
    }
    if (!pushes(next))
        return alongFace;
    const Vec2 out = offset - corner;
    const float distance = length(out);
    if (!(distance > 0.0f))
        return alongFace;
    const Vec2 normal = out * (1.0f / distance);
    return Touch{normal, distance - radius, dot(corner, normal) + radius, corner};
}

std::optional<Touch> atImpact(const Touch& touch, Vec2 offset, Vec2 motion, float radius) {
    if (!touch.corner || !(touch.gap > 0.0f) || !(radius > 0.0f))
        return touch;
    // |p + motion t| = radius, the first t in [0, 1].
    const Vec2 p = offset - *touch.corner;
    const float a = dot(motion, motion);
    const float b = dot(p, motion);
    const float c = dot(p, p) - radius * radius;
    const float discriminant = b * b - a * c;
    if (!(a > 0.0f) || discriminant < 0.0f)
        return std::nullopt;
    const float t = (-b - std::sqrt(discriminant)) / a;
    if (t < 0.0f || t > 1.0f)
        return std::nullopt;
    const Vec2 at = p + motion * t;
    const float distance = length(at);
    if (!(distance > 0.0f))
        return touch;
    const Vec2 normal = at * (1.0f / distance);
    return Touch{normal, dot(p, normal) - radius, dot(*touch.corner, normal) + radius,
                 touch.corner};
}

} // namespace jostle
