// Debug drawing of the pairs that touch: for each, a dot where they meet and a short line
// along the contact normal.
#pragma once

#include "drawn_contact.hpp"
#include "view.hpp"

#include <SDL.h>

namespace jostle::demo {

void drawContacts(SDL_Renderer* renderer, const World& world, const ContactSet& contacts,
                  const View& view);

} // namespace jostle::demo
