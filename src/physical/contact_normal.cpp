// Where a pair touches and which way its contact points (contact_normal.hpp).
#include "contact_normal.hpp"

#include "../one_way.hpp"
#include "../shapes.hpp"
#include "seams.hpp"
#include "step_context.hpp"

#include <algorithm>
#include <cmath>

namespace jostle {

namespace {

/// Apart along `normal` by `gap`, and neither body moving fast enough towards the other
/// to close it within the step. Each body's own speed counts, not only the pair's: two
/// boxes falling together do not approach, but when the lower one lands the upper one
/// must be stopped in the same step.
bool staysApart(const Body& a, const Body& b, Vec2 normal, float gap, float dt) {
    const float towardB = std::max(0.0f, -dot(a.velocity, normal));
    const float towardA = std::max(0.0f, dot(b.velocity, normal));
    return gap > 0.0f && gap > (towardA + towardB) * dt;
}

} // namespace

std::optional<Facing> chooseNormal(const StepContext& step, const Body& a, const Body& b) {
    const Vec2 d = a.position - b.position;
    const float gapX = std::abs(d.x) - (a.half.x + b.half.x);
    const float gapY = std::abs(d.y) - (a.half.y + b.half.y);
    const float skinX = step.skinOf(a.half.x, b.half.x);
    const float skinY = step.skinOf(a.half.y, b.half.y);
    // Apart along an axis by more than the skin, and not closing that gap in the step:
    // they never overlap along it, so they cannot touch (a box rising past a ledge it is
    // flush with does not meet the ledge's side).
    const Vec2 normalX{d.x < 0.0f ? -1.0f : 1.0f, 0.0f}, normalY{0.0f, d.y < 0.0f ? -1.0f : 1.0f};
    if ((gapX > skinX && staysApart(a, b, normalX, gapX, step.dt)) ||
        (gapY > skinY && staysApart(a, b, normalY, gapY, step.dt)))
        return std::nullopt;
    bool alongX = contactAxis(gapX, gapY, skinX, skinY) == kAlongX;
    if (gapX > skinX && gapY > skinY && (a.invMass == 0.0f || b.invMass == 0.0f)) {
        const std::optional<Hit> path =
            sweepBox(d, a.half + b.half, (a.velocity - b.velocity) * step.dt, Vec2{});
        if (!path)
            return std::nullopt;
        alongX = path->axis == kAlongX;
    }
    const bool oneStatic =
        a.type != b.type && (a.type == BodyType::Static || b.type == BodyType::Static);
    const bool deep = gapX < -skinX && gapY < -skinY; // overlapping beyond the skin
    if (oneStatic && !deep && step.world.shapedBodies > 0) {
        // Among ramps, a box's face may be covered anywhere along it (a ramp sitting on a
        // floor): the faces that push are those the level leaves bare where the body is,
        // and a box with none is inside the level, which the bodies around it stand for.
        const bool aStatic = a.type == BodyType::Static;
        const Body& wall = aStatic ? a : b;
        const Body& other = aStatic ? b : a;
        const std::uint8_t pushing = pushingFaces(step.world, wall, other);
        auto pushes = [&](bool x) {
            const float side = (x ? d.x : d.y) * (aStatic ? -1.0f : 1.0f);
            return (pushing & faceBit(x ? 0 : 1, side < 0.0f ? -1.0f : 1.0f)) != 0;
        };
        if (!pushes(alongX)) {
            // The other face, if the body is at it (not across it) and it is bare.
            alongX = !alongX;
            if ((alongX ? gapX < -skinX : gapY < -skinY) || !pushes(alongX))
                return std::nullopt;
        }
    } else if (gapX >= -skinX && gapY >= -skinY && oneStatic) {
        const bool aStatic = a.type == BodyType::Static;
        if (isSeam(step.world, aStatic ? a : b, aStatic ? b : a, alongX ? 0 : 1))
            alongX = !alongX;
    }
    const Facing facing = alongX ? Facing{normalX, gapX, skinX} : Facing{normalY, gapY, skinY};
    if (staysApart(a, b, facing.normal, facing.gap, step.dt))
        return std::nullopt;
    return facing;
}

std::optional<ShapedFacing> chooseShapedNormal(const StepContext& step, std::uint32_t slotA,
                                               std::uint32_t slotB) {
    const WorldState& w = step.world;
    const Body& a = w.slots[slotA];
    const Body& b = w.slots[slotB];
    auto isCut = [](const Body& body) {
        return body.shape == ShapeKind::Ramp || body.shape == ShapeKind::Segment;
    };
    if (isCut(a) && isCut(b))
        return std::nullopt; // ramps are infinitely heavy: two never push each other
    const bool aIsObstacle = isCut(a) || (!isCut(b) && a.invMass == 0.0f);
    const std::uint32_t moverSlot = aIsObstacle ? slotB : slotA;
    const std::uint32_t obstacleSlot = aIsObstacle ? slotA : slotB;
    const Body& mover = w.slots[moverSlot];
    const Body& obstacle = w.slots[obstacleSlot];
    const Shape& moverShape = w.shapes[moverSlot];
    const Shape& obstacleShape = w.shapes[obstacleSlot];
    const float r = moverShape.radius;
    const Outline outline = outlineOf(mover.half - Vec2{r, r}, r, obstacle.half, obstacleShape);
    const std::uint8_t pushing = pushingFaces(w, obstacle, mover);
    float apart = 0.0f;
    const Vec2 offset = mover.position - obstacle.position;
    std::optional<Touch> touch = touchOf(outline, offset, pushing, true, apart);
    if (!touch)
        return std::nullopt;
    touch =
        atImpact(*touch, offset, (mover.velocity - obstacle.velocity) * step.dt, outline.radius);
    if (!touch)
        return std::nullopt;
    const float size = std::min(reachOf(mover.half, moverShape, touch->normal),
                                reachOf(obstacle.half, obstacleShape, touch->normal));
    const float skin = std::max(2.0f * step.options.slop, kMinimumSkin) * size;
    const float reachable = (length(mover.velocity) + length(obstacle.velocity)) * step.dt;
    if ((apart > skin && apart > reachable) ||
        staysApart(mover, obstacle, touch->normal, touch->gap, step.dt))
        return std::nullopt;
    if (!stops(obstacle, touch->normal, touch->gap >= -skin, mover.dropThroughTime))
        return std::nullopt;
    return ShapedFacing{
        {aIsObstacle ? -touch->normal : touch->normal, touch->gap, skin}, touch->extent, size};
}

} // namespace jostle
