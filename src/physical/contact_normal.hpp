// Where a pair touches: the normal a contact of the step takes, the gap along it and the
// skin within which the pair touches, or nothing if the pair cannot meet in this step.
// For sharp boxes along an axis (chooseNormal); for a pair with a rounded body, a ramp or
// a segment along the outline (chooseShapedNormal).
#pragma once

#include "jostle/math.hpp"

#include <cstdint>
#include <optional>

namespace jostle {

struct StepContext;
struct Body;

/// The axis a pair touches along, as a unit normal from b towards a, with the gap
/// between them along it (negative: overlap) and the skin within which they touch.
struct Facing {
    Vec2 normal;
    float gap;
    float skin;
};

/// Where a contact's normal is chosen, or nothing if the pair cannot meet in this step:
/// apart along an axis by more than the skin, or along the chosen one at all, and not
/// closing that gap (staysApart). The axis is geometry.hpp's contactAxis, with two
/// exceptions at corners:
/// - A dynamic body apart on both axes from a static or kinematic one meets it where its
///   path across the step first touches it, and not at all if the path clears it: a box
///   rising past a ledge does not hit the ledge's side.
/// - If the corner is a seam between two static bodies, the face the contact would push
///   on is inside the level, and the other axis is the one. In a world with ramps, any
///   face the level covers where the body is (seams.hpp's pushingFaces) is inside it, and
///   the other face is the one if the body is at it and it is bare; else no contact. A
///   pair overlapping deeper than the skin goes the shallower way out, covered or not.
std::optional<Facing> chooseNormal(const StepContext& step, const Body& a, const Body& b);

/// A pair where one body is not a sharp box (shapes.hpp), as chooseNormal for boxes: the
/// normal (from b towards a, at any angle), gap and skin, and where the two touch along it.
struct ShapedFacing : Facing {
    float extent; ///< the value of (a - b) · normal at which the two touch
    float size;   ///< the smaller reach along the normal
};

/// Where a pair with a rounded body, a ramp or a segment touches, or nothing if it cannot
/// meet in this step. One body is the obstacle, whose outline the other's centre stays out
/// of: a ramp or segment if there is one, else a static or kinematic body, else b. Only
/// the faces of a static obstacle the level leaves bare push (seams.hpp's pushingFaces); a
/// segment pushes with its slope alone, and only what was on its side when the step began.
std::optional<ShapedFacing> chooseShapedNormal(const StepContext& step, std::uint32_t slotA,
                                               std::uint32_t slotB);

} // namespace jostle
