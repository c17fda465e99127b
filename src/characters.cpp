// Characters: walking along the ground, and rubbing only on floors.
#include "characters.hpp"

#include "integrate.hpp"
#include "world_state.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace jostle {

namespace {

/// "Right" across gravity: walking at a positive speed goes this way (+x in a y-down
/// world).
Vec2 rightOf(Vec2 down) {
    return {down.y, -down.x};
}

/// A push less than this along gravity is level: a wall's, not a slope's.
constexpr float kLevel = 1e-3f;

/// Whether a surface pushing `body` along `push` is a floor the character stands on.
bool isCharacterFloor(const Body& body, Vec2 push, Vec2 down) {
    return body.isCharacter() && surfaceOf(push, down, body.floorCos) == kFloor;
}

/// Whether character `id` lay against a slope too steep to stand on at the end of the last
/// step (one that pushed it up, but not as a floor) and does not walk away from it: it
/// slides down as the physics has it.
bool slidesDown(const WorldState& world, BodyId id, Vec2 right) {
    const Body& body = world.slots[id.index];
    const Vec2 down = world.events.down;
    bool slides = false;
    world.forEachContactOf(id, [&](BodyId, Vec2 push, const TouchRecord&) {
        const bool steep =
            dot(push, down) < -kLevel && surfaceOf(push, down, body.floorCos) != kFloor;
        slides = slides || (steep && body.walkSpeed * dot(push, right) <= 0.0f);
    });
    return slides;
}

/// Whether character `id` pressed, at the end of the last step, against a dynamic body on
/// the side it walks to (a wall to it, not its floor). Walking does not speed it up into
/// that body: its feet push it, through its floor's friction, as hard as they grip.
bool walksIntoABody(const WorldState& world, BodyId id, Vec2 right, float walk) {
    const Body& body = world.slots[id.index];
    const Vec2 down = world.events.down;
    bool into = false;
    world.forEachContactOf(id, [&](BodyId other, Vec2 push, const TouchRecord&) {
        into = into || (world.slots[other.index].isDynamic() && walk * dot(push, right) < 0.0f &&
                        (surfaceOf(push, down, body.floorCos) & (kWallLeft | kWallRight)) != 0);
    });
    return into;
}

/// What walking adds along gravity on a floor of normal `floor` (pointing up from it):
/// relative to the floor, the character goes along it, and its speed away from it (a
/// jump, or gravity's pull into it) stays as it was. On a slope, walking across gravity
/// is walking up or down along gravity too: a character that stops stops there, one that
/// turns round walks down at once. 0 on a level floor, exactly.
float alongGravityOnFloor(Vec2 relative, Vec2 floor, Vec2 right, Vec2 down, float walk) {
    const float away = dot(relative, floor);
    return (away - walk * dot(floor, right)) / dot(floor, down) - dot(relative, down);
}

} // namespace

void walkCharacters(WorldState& world) {
    const Vec2 down = world.events.down;
    const Vec2 right = rightOf(down);
    for (BodyId id : world.movers()) {
        Body& body = world.slots[id.index];
        if (!body.isCharacter() || body.asleep)
            continue;
        const GroundRecord ground = groundOf(world, id);
        if (ground.body.isNull() && slidesDown(world, id, right))
            continue;
        const Vec2 under = ground.body.isNull()
                               ? Vec2{}
                               : world.slots[ground.body.index].surfaceMotion(ground.normal);
        const float now = dot(body.velocity, right);
        float across = dot(under, right) + body.walkSpeed;
        float walk = body.walkSpeed;
        if (walk != 0.0f && walksIntoABody(world, id, right, walk)) {
            across = walk > 0.0f ? std::min(across, now) : std::max(across, now);
            walk = across - dot(under, right);
        }
        Vec2 walked = body.velocity + right * (across - now);
        if (!ground.body.isNull())
            walked +=
                down * alongGravityOnFloor(body.velocity - under, ground.normal, right, down, walk);
        body.velocity = withinRange(walked);
    }
}

float frictionAgainst(const Body& body, Vec2 push, Vec2 down) {
    if (!body.isCharacter() || surfaceOf(push, down, body.floorCos) == kFloor)
        return body.friction;
    return body.wallFriction;
}

Vec2 walkOver(const Body& a, const Body& b, Vec2 normal, Vec2 down) {
    const Vec2 right = rightOf(down);
    Vec2 walk;
    if (isCharacterFloor(a, normal, down))
        walk = right * a.walkSpeed;
    else if (isCharacterFloor(b, -normal, down))
        walk = right * -b.walkSpeed;
    // A conveyor's surface moves under what rubs on it, along the surface: a keeps pace
    // with b's surface.
    if (a.surfaceVelocity != Vec2{} || b.surfaceVelocity != Vec2{}) {
        const Vec2 belt = b.surfaceVelocity - a.surfaceVelocity;
        walk += belt - normal * dot(belt, normal);
    }
    return walk;
}

bool keepsATangentSpeed(const Body& a, const Body& b, bool conveyors) {
    return a.character || b.character ||
           (conveyors && (a.surfaceVelocity != Vec2{} || b.surfaceVelocity != Vec2{}));
}

float walkAlongSlope(const Body& a, const Body& b, Vec2 normal, Vec2 down) {
    const Vec2 right = rightOf(down);
    const Vec2 tangent{-normal.y, normal.x};
    const float across = dot(tangent, right);
    if (across == 0.0f || std::abs(dot(normal, down)) >= 1.0f)
        return std::numeric_limits<float>::quiet_NaN();
    float walk;
    if (isCharacterFloor(a, normal, down))
        walk = a.walkSpeed / across;
    else if (isCharacterFloor(b, -normal, down))
        walk = -b.walkSpeed / across;
    else
        return std::numeric_limits<float>::quiet_NaN();
    // A conveyor's surface, along the slope, under the walk.
    if (a.surfaceVelocity != Vec2{} || b.surfaceVelocity != Vec2{})
        walk += dot(b.surfaceVelocity - a.surfaceVelocity, tangent);
    return walk;
}

} // namespace jostle
