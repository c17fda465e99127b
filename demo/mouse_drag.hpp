// Left-drag: moves a dynamic body towards the cursor by setting its velocity every step,
// never its position, so that it still collides with everything on its way.
#pragma once

#include "sample.hpp"

namespace jostle::demo {

class MouseDrag {
public:
    /// Grabs the dynamic body under `point` in `pane`, if there is one.
    void grab(Pane& pane, Vec2 point);
    void moveTo(Vec2 point) { target_ = point; }
    void release() { world_ = nullptr; }
    /// Sets the grabbed body's velocity towards the cursor; call before each step.
    void pull(float dt) const;
    /// True while a body is held (and still exists).
    bool holding() const { return world_ != nullptr && world_->isValid(body_); }
    /// The held body's centre; only while holding().
    Vec2 heldPosition() const { return world_->position(body_); }

private:
    World* world_ = nullptr;
    BodyId body_;
    Vec2 target_;
};

} // namespace jostle::demo
