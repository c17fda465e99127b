// Drawing one pane: its world's bodies as filled boxes in `jostle render`'s colours, its
// title and labels, and with debug drawing on, sleeping bodies dimmed, the sides each
// body touches, its velocity, every touching pair's contact point and normal, a picture
// of the broadphase grid under the bodies, and a legend.
#pragma once

#include "sample.hpp"
#include "view.hpp"

#include <SDL.h>

namespace jostle::demo {

/// `dt` is the worlds' step, which the broadphase picture grows moving boxes by.
void drawPane(SDL_Renderer* renderer, const Pane& pane, const View& view, bool debug, float dt);

} // namespace jostle::demo
