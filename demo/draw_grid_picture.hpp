// Drawing the broadphase picture (grid_picture.hpp) in the SDL window.
#pragma once

#include "grid_picture.hpp"
#include "view.hpp"

#include <SDL.h>

namespace jostle::demo {

/// Draws `picture` under the bodies: faint lines of its main level's cells, the cells its
/// boxes are filed in tinted (main level) or outlined (the others, coarser or finer), and
/// boxes grown by their motion outlined where the growth shows.
void drawGridPicture(SDL_Renderer* renderer, const GridPicture& picture, const View& view);

} // namespace jostle::demo
