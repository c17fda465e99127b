// shared/drawn_shape.hpp: a body's shape as the pictures draw it (`jostle render` and the
// demo): a box, a rounded box (a circle when hw = hh = radius, a capsule when one half
// extent is the radius), a ramp's triangle, or a segment, the ramp's sloped face alone.
// Read from World::bodyDef, so it is the shape the world was given, nothing of the solver.
//
//     const jostle::shared::DrawnShape shape = jostle::shared::DrawnShape::of(world, body);
//     if (shape.kind == jostle::shared::DrawnKind::Ramp)
//         drawTriangle(shape.triangle());
#pragma once

#include "jostle/world.hpp"

#include <array>
#include <vector>

namespace jostle::shared {

enum class DrawnKind { Box, Rounded, Ramp, Segment };

struct DrawnShape {
    DrawnKind kind = DrawnKind::Box;
    Vec2 centre;
    Vec2 half;
    float radius = 0.0f; ///< Rounded: the corners' radius, at most min(half.x, half.y)
    Vec2 slope;          ///< Ramp, Segment: the corner the sloped face looks towards

    /// The shape of `body` where it is now.
    static DrawnShape of(const World& world, BodyId body);

    /// The same shape seen through a camera that puts its centre at `seenCentre` and
    /// scales lengths by `scale` (> 0), as a picture's pixels see it.
    DrawnShape mapped(Vec2 seenCentre, float scale) const;

    /// True if `point` is in the shape, its edge included. A segment, a line, holds none.
    bool contains(Vec2 point) const;

    /// A ramp's or segment's triangle: the box's corners other than the one `slope` names.
    /// The first two are the ends of the sloped face, the third the right angle's corner.
    std::array<Vec2, 3> triangle() const;

    /// The sloped face's outward normal (unit): towards the corner `slope` names, the side
    /// from which a segment blocks.
    Vec2 faceNormal() const;

    /// The edge of the shape as a convex polygon, in order around it: a box's 4 corners, a
    /// ramp's 3, a segment's 2 ends; a rounded box's straight sides joined by arcs of
    /// `arcPoints` points each (>= 2), exact at both ends of every arc.
    std::vector<Vec2> perimeter(int arcPoints) const;
};

} // namespace jostle::shared
