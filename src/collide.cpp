#include "collide.hpp"

namespace jostle {

std::optional<Vec2> shortestSeparation(const Box& a, const Box& b) {
    // distance between the rects
    const float dx = a.centre.x - b.centre.x;
    const float dy = a.centre.y - b.centre.y;
    const float adx = std::abs(dx);
    const float ady = std::abs(dy);
    // sum of the extents
    const float shw = a.half.x + b.half.x;
    const float shh = a.half.y + b.half.y;
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

std::optional<Hit> sweepBox(const Box& a, Vec2 motion, const Box& b, Vec2 skin) {
    // a's centre moving along `motion` against b grown by a's half extents (Minkowski
    // sum), shrunk by the skin: a ray against a box, one slab per axis.
    const Vec2 reach{b.half.x + a.half.x - skin.x, b.half.y + a.half.y - skin.y};
    if (reach.x <= 0.0f || reach.y <= 0.0f)
        return std::nullopt;
    const float start[2] = {a.centre.x - b.centre.x, a.centre.y - b.centre.y};
    const float move[2] = {motion.x, motion.y};
    const float half[2] = {reach.x, reach.y};
    float enter = -INFINITY, leave = INFINITY;
    int enterAxis = -1;
    for (int axis = 0; axis < 2; ++axis) {
        if (move[axis] == 0.0f) {
            if (start[axis] <= -half[axis] || start[axis] >= half[axis])
                return std::nullopt; // never inside this slab
            continue;
        }
        float t0 = (-half[axis] - start[axis]) / move[axis];
        float t1 = (half[axis] - start[axis]) / move[axis];
        if (t0 > t1)
            std::swap(t0, t1);
        if (t0 > enter) {
            enter = t0;
            enterAxis = axis;
        }
        leave = std::min(leave, t1);
    }
    if (enterAxis < 0 || enter < 0.0f || enter > 1.0f || enter >= leave)
        return std::nullopt;
    Vec2 normal{0.0f, 0.0f};
    if (enterAxis == 0)
        normal.x = move[0] > 0.0f ? -1.0f : 1.0f;
    else
        normal.y = move[1] > 0.0f ? -1.0f : 1.0f;
    return Hit{enter, normal};
}

Axis contactAxis(float gapX, float gapY, float skinX, float skinY) {
    const bool overlapX = gapX < -skinX;
    const bool overlapY = gapY < -skinY;
    if (overlapX && overlapY)
        return gapX > gapY ? Axis::X : Axis::Y;
    if (overlapY)
        return Axis::X;
    if (overlapX)
        return Axis::Y;
    if (gapY <= skinY)
        return Axis::Y;
    if (gapX <= skinX)
        return Axis::X;
    return gapX > gapY ? Axis::X : Axis::Y;
}

} // namespace jostle
