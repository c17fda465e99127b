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
