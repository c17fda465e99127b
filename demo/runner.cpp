// Steering a character: see runner.hpp.
#include "runner.hpp"

#include <cmath>

namespace jostle::demo {

namespace {

/// Long enough to fall clear of a thin platform at rest (g t² / 2 covers it), short
/// enough not to fall through the next one down.
constexpr float kDropThroughSeconds = 0.25f;

} // namespace

float JumpDef::takeOffSpeed() const {
    return std::sqrt(2.0f * gravity() * height);
}

void Runner::steer(World& world, const Controls& controls) const {
    if (!world.isValid(body_))
        return;
    Vec2 velocity = world.velocity(body_);
    const float direction = (controls.right ? 1.0f : 0.0f) - (controls.left ? 1.0f : 0.0f);
    // A character walks (along slopes, with what it stands on); another body is moved.
    if (world.isCharacter(body_)) {
        if (world.walkSpeed(body_) != direction * runSpeed_)
            world.setWalkSpeed(body_, direction * runSpeed_);
    } else {
        velocity.x = direction * runSpeed_;
    }
    const bool standing = world.touching(body_).floor;
    if (controls.jumpPressed && standing) {
        if (controls.down)
            world.dropThrough(body_, kDropThroughSeconds);
        else
            velocity.y = -jump_.takeOffSpeed(); // y grows downward
    }
    // Only when it changes: setting a velocity wakes the body, and a character left alone
    // may fall asleep like any other body.
    if (velocity.x != world.velocity(body_).x || velocity.y != world.velocity(body_).y)
        world.setVelocity(body_, velocity);
}

} // namespace jostle::demo
