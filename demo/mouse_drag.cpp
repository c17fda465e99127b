// Dragging a body with the mouse: see mouse_drag.hpp.
#include "mouse_drag.hpp"

#include "jostle/query.hpp"

namespace jostle::demo {

namespace {

/// The fraction of the distance to the cursor to cover in one step: the whole of it
/// would make the body overshoot as soon as gravity or a contact adds to its velocity.
constexpr float kCatchUpPerStep = 0.3f;

} // namespace

void MouseDrag::grab(Pane& pane, Vec2 point) {
    release();
    for (BodyId body : queryPoint(*pane.world, point)) {
        if (pane.world->type(body) == BodyType::Dynamic) {
            world_ = pane.world.get();
            body_ = body;
            target_ = point;
            return;
        }
    }
}

void MouseDrag::pull(float dt) const {
    if (world_ == nullptr || !world_->isValid(body_))
        return;
    const Vec2 gap = target_ - world_->position(body_);
    world_->setVelocity(body_, gap * (kCatchUpPerStep / dt));
}

} // namespace jostle::demo
