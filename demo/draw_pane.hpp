// Drawing one pane: its world's bodies as filled boxes in `jostle render`'s colours, its
// title and labels, and with debug drawing on, sleeping bodies dimmed and the sides each
// body touches, its velocity and the normals of contacts that just began.
#pragma once

#include "sample.hpp"

#include <SDL.h>

namespace jostle::demo {

void drawPane(SDL_Renderer* renderer, const Pane& pane, const View& view, bool debug);

} // namespace jostle::demo
