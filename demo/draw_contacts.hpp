// Debug drawing of the pairs that touch: for each, a dot where they meet and a short line
// along the contact normal.
#pragma once

#include "contact_set.hpp"
#include "view.hpp"

#include <SDL.h>

namespace jostle::demo {

/// Where the two boxes of `pair` meet: across the normal, the middle of the stretch their
/// faces share (of the gap between them, should they no longer share one); along it,
/// halfway between the two faces that touch.
Vec2 contactPoint(const World& world, const TouchingPair& pair);

void drawContacts(SDL_Renderer* renderer, const World& world, const ContactSet& contacts,
                  const View& view);

} // namespace jostle::demo
