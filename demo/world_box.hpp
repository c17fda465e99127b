// A box of a world by its corners, as the samples give the part of their world a pane
// shows; SDL-free, so that the samples build without a window (the web page too).
#pragma once

#include "jostle/math.hpp"

namespace jostle::demo {

/// A box of a world by its corners; y grows downward, as on screen.
struct WorldBox {
    Vec2 min;
    Vec2 max;
};

} // namespace jostle::demo
