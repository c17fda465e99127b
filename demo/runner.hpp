// A character steered by the keys: runs left and right, jumps from the floor, and drops
// through one-way platforms on down + jump. Shared by the platformer and the crates.
//
// The jump is given as a height and the time to reach it, as the tutorial's platformer
// companion does, because that is what a designer tunes: gravity = 2 h / t² and the
// take-off speed sqrt(2 g h) follow from them (so the world's gravity comes from here).
#pragma once

#include "sample.hpp"

namespace jostle::demo {

struct JumpDef {
    float height = 0.0f;     ///< how high the character's feet rise, in world units
    float timeToApex = 0.0f; ///< seconds from take-off to the top of the jump

    float gravity() const { return 2.0f * height / (timeToApex * timeToApex); }
    float takeOffSpeed() const;
};

class Runner {
public:
    Runner() = default;
    Runner(BodyId body, float runSpeed, JumpDef jump)
        : body_(body), runSpeed_(runSpeed), jump_(jump) {}

    BodyId body() const { return body_; }
    /// Sets the horizontal velocity from the keys (a character's walk speed, for a
    /// character), jumps when standing, drops through one-way platforms on down + jump.
    void steer(World& world, const Controls& controls) const;

private:
    BodyId body_;
    float runSpeed_ = 0.0f;
    JumpDef jump_;
};

} // namespace jostle::demo
