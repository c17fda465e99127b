// A body's shape for drawing: see drawn_shape.hpp.
#include "drawn_shape.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace jostle::shared {

DrawnShape DrawnShape::of(const World& world, BodyId body) {
    const BodyDef def = world.bodyDef(body);
    DrawnShape shape;
    shape.centre = world.position(body);
    shape.half = world.halfExtents(body);
    shape.radius = def.radius;
    shape.slope = def.slope;
    if (def.slope != Vec2{})
        shape.kind = def.segment ? DrawnKind::Segment : DrawnKind::Ramp;
    else if (def.radius > 0.0f)
        shape.kind = DrawnKind::Rounded;
    return shape;
}

DrawnShape DrawnShape::mapped(Vec2 seenCentre, float scale) const {
    DrawnShape shape = *this;
    shape.centre = seenCentre;
    shape.half = half * scale;
    shape.radius = radius * scale;
    return shape;
}

bool DrawnShape::contains(Vec2 point) const {
    const Vec2 d = point - centre;
    if (kind == DrawnKind::Segment || std::abs(d.x) > half.x || std::abs(d.y) > half.y)
        return false;
    switch (kind) {
    case DrawnKind::Rounded: {
        // Beyond the core (the box shrunk by the radius), within the radius of it.
        const float ox = std::max(std::abs(d.x) - (half.x - radius), 0.0f);
        const float oy = std::max(std::abs(d.y) - (half.y - radius), 0.0f);
        return ox * ox + oy * oy <= radius * radius;
    }
    case DrawnKind::Ramp:
        // Behind the diagonal through the centre, as seen from the corner cut away.
        return slope.x * half.y * d.x + slope.y * half.x * d.y <= 0.0f;
    case DrawnKind::Box:
    case DrawnKind::Segment:
        break;
    }
    return true;
}

std::array<Vec2, 3> DrawnShape::triangle() const {
    return {centre + Vec2{slope.x * half.x, -slope.y * half.y},
            centre + Vec2{-slope.x * half.x, slope.y * half.y},
            centre + Vec2{-slope.x * half.x, -slope.y * half.y}};
}

Vec2 DrawnShape::faceNormal() const {
    const Vec2 n{slope.x * half.y, slope.y * half.x};
    return n * (1.0f / length(n));
}

std::vector<Vec2> DrawnShape::perimeter(int arcPoints) const {
    switch (kind) {
    case DrawnKind::Ramp: {
        const auto corners = triangle();
        return {corners.begin(), corners.end()};
    }
    case DrawnKind::Segment: {
        const auto corners = triangle();
        return {corners[0], corners[1]};
    }
    case DrawnKind::Box:
    case DrawnKind::Rounded:
        break;
    }
    // A box is a rounded box of radius 0: each arc shrinks to its corner.
    const int points = kind == DrawnKind::Box ? 1 : std::max(arcPoints, 2);
    const Vec2 core = half - Vec2{radius, radius};
    // The arcs' centres, each with the angle its arc starts at, going round the box.
    const std::array<Vec2, 4> corners{
        {{core.x, core.y}, {-core.x, core.y}, {-core.x, -core.y}, {core.x, -core.y}}};
    std::vector<Vec2> result;
    result.reserve(static_cast<std::size_t>(4 * points));
    for (int corner = 0; corner < 4; ++corner)
        for (int i = 0; i < points; ++i) {
            const double step = points > 1 ? double(i) / double(points - 1) : 0.5;
            const double angle = (double(corner) + step) * std::numbers::pi / 2.0;
            const Vec2 offset{float(std::cos(angle)) * radius, float(std::sin(angle)) * radius};
            result.push_back(centre + corners[static_cast<std::size_t>(corner)] + offset);
        }
    return result;
}

} // namespace jostle::shared
