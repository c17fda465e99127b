// The demo's own colours: its background, text and pane borders. The world's shapes and
// debug marks are drawn in the library's (jostle::DebugPalette), as `jostle render`'s are.
#pragma once

#include <SDL.h>

namespace jostle::demo {

constexpr SDL_Color kBackground{24, 26, 33, 255};
constexpr SDL_Color kText{230, 230, 230, 255};
constexpr SDL_Color kTextDim{120, 124, 135, 255};
constexpr SDL_Color kTextHighlight{255, 210, 90, 255};
constexpr SDL_Color kPaneBorder{60, 64, 76, 255};

constexpr SDL_Color scaled(SDL_Color colour, int percent) {
    return {static_cast<Uint8>(colour.r * percent / 100),
            static_cast<Uint8>(colour.g * percent / 100),
            static_cast<Uint8>(colour.b * percent / 100), colour.a};
}

inline void setColour(SDL_Renderer* renderer, SDL_Color colour) {
    SDL_SetRenderDrawColor(renderer, colour.r, colour.g, colour.b, colour.a);
}

} // namespace jostle::demo
