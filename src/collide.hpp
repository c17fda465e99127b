// Overlap tests between axis-aligned boxes.
#pragma once

#include "jostle/math.hpp"

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

} // namespace jostle
