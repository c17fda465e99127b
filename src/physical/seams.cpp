// Seams between static boxes. A box sliding along a floor of separate boxes, or along a
// wall whose rows are separate boxes, meets the next box at such a corner; a contact
// pushing on that face would stop it dead at the seam.
#include "seams.hpp"

#include "../world_state.hpp"

#include <algorithm>
#include <cmath>

namespace jostle {

namespace {

/// Whether `cover`, lying on the `side` of a face along `axis`, has a whole face flush
/// against it: a box's, or a ramp's leg (the faces away from its slope).
bool coversWith(const WorldState& world, const Body& cover, int axis, float side) {
    if (cover.isBox())
        return true;
    return cover.shape == ShapeKind::Ramp &&
           world.shapes[std::size_t(&cover - world.slots.data())].slope[axis] == side;
}

/// Whether the face of static `wall` on `side` along `axis` is covered from `from` to `to`
/// along it by one other static body flush against it: on the other side of the face
/// within a hair, and spanning that stretch. A hair is a small fraction of the sizes, or
/// a few float steps at the face's coordinate (metre-sized tiles far from the origin round
/// coarser than that fraction).
bool coveredBetween(const WorldState& world, const Body& wall, const Body& other, int axis,
                    float side, float from, float to) {
    const int along = 1 - axis;
    const float face = wall.position[axis] + side * wall.half[axis];
    const float tolerance =
        std::max(1e-4f * std::max(wall.half[axis], other.half[axis]), 4.0f * ulpOf(face));
    Box probe;
    probe.min[axis] = probe.max[axis] = face + side * tolerance;
    probe.min[along] = from;
    probe.max[along] = to;
    bool covered = false;
    world.restingGrid.query(probe, [&](std::uint32_t k) {
        const Body& cover = world.slots[world.restingSlots[k]];
        if (covered || cover.type != BodyType::Static || &cover == &wall ||
            !coversWith(world, cover, axis, side))
            return;
        const Box coverBounds = cover.box();
        const float near = side > 0.0f ? coverBounds.min[axis] : coverBounds.max[axis];
        if (std::abs(near - face) > tolerance)
            return;
        covered =
            coverBounds.min[along] <= from + tolerance && coverBounds.max[along] >= to - tolerance;
    });
    return covered;
}

/// A ramp's tip at the end of its face along `axis` (the face its slope has a side on).
Vec2 tipOf(const Body& ramp, Vec2 slope, int axis) {
    Vec2 tip;
    tip[axis] = ramp.position[axis] + slope[axis] * ramp.half[axis];
    tip[1 - axis] = ramp.position[1 - axis] - slope[1 - axis] * ramp.half[1 - axis];
    return tip;
}

/// Whether another static ramp of the same slope and steepness goes on from `wall`'s tip
/// on its face along `axis`: two ramp tiles in a line, whose shared tip is no corner.
bool rampGoesOn(const WorldState& world, const Body& wall, Vec2 slope, int axis) {
    const Vec2 tip = tipOf(wall, slope, axis);
    const float tolerance = std::max(1e-4f * std::min(wall.half.x, wall.half.y),
                                     4.0f * ulpOf(std::max(std::abs(tip.x), std::abs(tip.y))));
    const Box probe{tip - Vec2{tolerance, tolerance}, tip + Vec2{tolerance, tolerance}};
    bool goesOn = false;
    world.restingGrid.query(probe, [&](std::uint32_t k) {
        const std::uint32_t slot = world.restingSlots[k];
        const Body& next = world.slots[slot];
        if (goesOn || &next == &wall || next.type != BodyType::Static ||
            next.shape != ShapeKind::Ramp || world.shapes[slot].slope != slope)
            return;
        const float steepness = wall.half.y * next.half.x - wall.half.x * next.half.y;
        if (std::abs(steepness) > 1e-4f * wall.half.x * next.half.x)
            return;
        const Vec2 otherTip = tipOf(next, slope, 1 - axis);
        goesOn =
            std::abs(otherTip.x - tip.x) <= tolerance && std::abs(otherTip.y - tip.y) <= tolerance;
    });
    return goesOn;
}

/// Whether the ground a ramp stands on (what covers its leg along `along`) goes on beyond
/// its tip at the end of the face along `axis`, for as far as `other` is wide: what comes
/// along that ground meets the tip on its slope.
bool groundGoesOn(const WorldState& world, const Body& wall, const Body& other, Vec2 slope,
                  int axis) {
    const int along = 1 - axis;
    const float tip = wall.position[axis] + slope[axis] * wall.half[axis];
    const float beyond = tip + slope[axis] * 2.0f * other.half[axis];
    return coveredBetween(world, wall, other, along, -slope[along], std::min(tip, beyond),
                          std::max(tip, beyond));
}

/// Whether the face of static `wall` on `side` along `axis` is covered by another static
/// body where `other` spans it (the whole stretch of the face beside `other`). A ramp's
/// face that ends in a tip is covered where the next ramp of a line goes on from the tip,
/// or the ground under the ramp goes on beyond it.
bool isCovered(const WorldState& world, const Body& wall, const Body& other, int axis, float side) {
    if (wall.shape == ShapeKind::Ramp) {
        const Vec2 slope = world.shapes[std::size_t(&wall - world.slots.data())].slope;
        if (slope[axis] == side &&
            (rampGoesOn(world, wall, slope, axis) || groundGoesOn(world, wall, other, slope, axis)))
            return true;
    }
    const int along = 1 - axis;
    const Box wallBox = wall.box(), otherBox = other.box();
    float from = std::max(wallBox.min[along], otherBox.min[along]);
    float to = std::min(wallBox.max[along], otherBox.max[along]);
    if (from > to)
        from = to = std::clamp(other.position[along], wallBox.min[along], wallBox.max[along]);
    return coveredBetween(world, wall, other, axis, side, from, to);
}

} // namespace

std::uint8_t pushingFaces(const WorldState& world, const Body& wall, const Body& other) {
    if (wall.shape == ShapeKind::Segment)
        return 0;
    if (wall.type != BodyType::Static)
        return kAllFaces;
    std::uint8_t faces = 0;
    for (int axis = 0; axis < 2; ++axis)
        for (float side : {-1.0f, 1.0f})
            if (!isCovered(world, wall, other, axis, side))
                faces |= faceBit(axis, side);
    return faces;
}

bool isSeam(const WorldState& world, const Body& wall, const Body& other, int axis) {
    const int along = 1 - axis; // the axis the face runs along
    // The face on the side of `other`, and its corner nearest `other`; `inward` runs from it
    // along the face.
    const float side = other.position[axis] < wall.position[axis] ? -1.0f : 1.0f;
    const float end = other.position[along] < wall.position[along] ? -1.0f : 1.0f;
    const float corner = wall.position[along] + end * wall.half[along];
    const float inward = -end;
    // It must cover the face from the corner inward, a good part of the way.
    const float reach = 0.25f * std::min(wall.half[along], other.half[along]);
    return coveredBetween(world, wall, other, axis, side, std::min(corner, corner + inward * reach),
                          std::max(corner, corner + inward * reach));
}

} // namespace jostle
