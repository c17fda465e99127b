// The geometry of boxes (geometry.hpp states the rules).
#include "geometry.hpp"

#include <limits>

namespace jostle {

namespace {

/// A point moving from the origin by `motion` through a box given relative to where it
/// starts (the slab method): per axis, when it enters the slab between that axis's two
/// faces (-infinity along an axis it does not move along), and when it first leaves one.
struct Crossing {
    float enter[2] = {-kInfinity, -kInfinity};
    float leave = kInfinity;

    /// The axis whose slab it enters last, where it enters the box; a tie goes to y, or to
    /// x when `tieToX`.
    Axis entryAxis(bool tieToX = false) const {
        return (tieToX ? enter[1] > enter[0] : enter[1] >= enter[0]) ? kAlongY : kAlongX;
    }
};

/// The one primitive of everything that moves through a box. Nothing when the point is
/// never inside: parallel to a slab and outside it, where on a face is inside only for a
/// `closed` box.
std::optional<Crossing> cross(const Box& box, Vec2 motion, bool closed) {
    Crossing c;
    for (int axis = 0; axis < 2; ++axis) {
        const float low = box.min[axis], high = box.max[axis], move = motion[axis];
        if (move == 0.0f) {
            const bool inside = closed ? low <= 0.0f && high >= 0.0f : low < 0.0f && high > 0.0f;
            if (!inside)
                return std::nullopt;
            continue;
        }
        const float toLow = low / move, toHigh = high / move;
        c.enter[axis] = std::min(toLow, toHigh);
        c.leave = std::min(c.leave, std::max(toLow, toHigh));
    }
    return c;
}

/// The box b grown by a's half extents, around a's centre: what a's centre crosses.
Box grown(Vec2 offset, Vec2 reach) {
    return {-reach - offset, reach - offset};
}

/// The unit normal of the face met along `axis`, against the motion.
Vec2 faceNormal(int axis, Vec2 motion) {
    Vec2 normal{0.0f, 0.0f};
    normal[axis] = motion[axis] > 0.0f ? -1.0f : 1.0f;
    return normal;
}

} // namespace

std::optional<Vec2> shortestSeparation(Vec2 offset, Vec2 reach) {
    // distance between the rects
    const float dx = offset.x;
    const float dy = offset.y;
    const float adx = std::abs(dx);
    const float ady = std::abs(dy);
    // sum of the extents
    const float shw = reach.x;
    const float shh = reach.y;
    if (adx >= shw || ady >= shh)
        return std::nullopt;
    // shortest separation; ignore the longer axis (a tie keeps y)
    float sx = shw - adx;
    float sy = shh - ady;
    if (sx < sy) {
        if (sx > 0.0f)
            sy = 0.0f;
    } else if (sy > 0.0f) {
        sx = 0.0f;
    }
    // correct sign
    if (dx < 0.0f)
        sx = -sx;
    if (dy < 0.0f)
        sy = -sy;
    return Vec2{sx, sy};
}

Axis contactAxis(float gapX, float gapY, float skinX, float skinY) {
    const bool overlapX = gapX < -skinX;
    const bool overlapY = gapY < -skinY;
    if (overlapX && overlapY)
        return gapX > gapY ? kAlongX : kAlongY;
    if (overlapY)
        return kAlongX;
    if (overlapX)
        return kAlongY;
    if (gapY <= skinY)
        return kAlongY;
    if (gapX <= skinX)
        return kAlongX;
    return gapX > gapY ? kAlongX : kAlongY;
}

std::optional<Hit> sweepBox(Vec2 offset, Vec2 reach, Vec2 motion, Vec2 skin) {
    const Vec2 deep = reach - skin;
    if (deep.x <= 0.0f || deep.y <= 0.0f)
        return std::nullopt;
    const std::optional<Crossing> c = cross(grown(offset, deep), motion, false);
    if (!c)
        return std::nullopt;
    const Axis axis = c->entryAxis(true);
    const float enter = c->enter[axis];
    if (enter < 0.0f || enter > 1.0f || enter >= c->leave)
        return std::nullopt;
    return Hit{enter, faceNormal(axis, motion), axis};
}

std::optional<Hit> castBox(Vec2 offset, Vec2 reach, Vec2 motion, Vec2 skin) {
    const Vec2 deep = reach - skin;
    if (deep.x <= 0.0f || deep.y <= 0.0f || (motion.x == 0.0f && motion.y == 0.0f))
        return std::nullopt;
    // Deeper than the skin (the box shrunk by it), and touching (the box as it is).
    const std::optional<Crossing> penetrate = cross(grown(offset, deep), motion, false);
    const std::optional<Crossing> touch = cross(grown(offset, reach), motion, false);
    if (!penetrate || !touch)
        return std::nullopt;
    const Axis axis = penetrate->entryAxis();
    const float enter = penetrate->enter[axis];
    // Never deeper than the skin on both axes at once; or already that deep at the start
    // (inside, free to leave).
    if (!(enter < penetrate->leave) || enter < 0.0f)
        return std::nullopt;
    // Touching comes at or before penetrating, and may be before the start (overlapping
    // within the skin: moving in stops at once).
    const Axis touchAxis = touch->entryAxis();
    const float time = touch->enter[touchAxis];
    if (time > 1.0f)
        return std::nullopt;
    if (time <= 0.0f)
        return Hit{0.0f, faceNormal(axis, motion), kFromInside};
    return Hit{time, faceNormal(axis, motion), touchAxis};
}

std::optional<Hit> castRay(Vec2 from, Vec2 delta, const Box& box) {
    if (delta.x == 0.0f && delta.y == 0.0f)
        return std::nullopt; // no direction: nothing to meet
    const std::optional<Crossing> c = cross({box.min - from, box.max - from}, delta, true);
    if (!c)
        return std::nullopt;
    const Axis axis = c->entryAxis();
    const float entry = c->enter[axis];
    // entry == leave is a grazed corner: it counts. leave <= 0: the ray starts on the box's
    // far side, heading away.
    if (entry > c->leave || entry > 1.0f || c->leave <= 0.0f)
        return std::nullopt;
    if (entry >= 0.0f)
        return Hit{entry, faceNormal(axis, delta), axis};
    // Inside from the start: the face the ray heads for along its main direction.
    const int heading = std::abs(delta.y) >= std::abs(delta.x) ? 1 : 0;
    return Hit{0.0f, faceNormal(heading, delta), kFromInside};
}

} // namespace jostle
