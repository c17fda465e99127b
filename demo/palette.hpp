// The demo's colours: those of `jostle render` (tools/jostle/render.cpp), so that the
// window and the GIFs look alike, plus a few for text and debug marks.
#pragma once

#include "jostle/body.hpp"

#include <SDL.h>

#include <array>

namespace jostle::demo {

constexpr SDL_Color kBackground{24, 26, 33, 255};
/// Indexed by BodyType: static grey, kinematic blue, dynamic orange.
constexpr std::array<SDL_Color, 3> kTypeColours{{
    {150, 150, 150, 255},
    {70, 130, 230, 255},
    {240, 150, 60, 255},
}};
/// Outlines are darker, so that boxes side by side (a pyramid, a tile floor) stay apart;
/// sleeping bodies dimmer, so that one can see which have come to rest.
constexpr int kOutlinePercent = 60;
constexpr int kSleepingPercent = 55;

constexpr SDL_Color kText{230, 230, 230, 255};
constexpr SDL_Color kTextDim{120, 124, 135, 255};
constexpr SDL_Color kTextHighlight{255, 210, 90, 255};
constexpr SDL_Color kPaneBorder{60, 64, 76, 255};
/// Debug marks: the sides a body touches, its velocity, the touching pairs' contact
/// points and normals.
constexpr SDL_Color kTouching{230, 60, 60, 255};
constexpr SDL_Color kVelocity{90, 220, 120, 255};
constexpr SDL_Color kContact{250, 250, 120, 255};
/// The broadphase picture, under the bodies: lines of the main level's cells just off
/// the background, so they read as paper rather than as things; the cells that hold boxes
/// tinted (blended, so the lines show through), other levels' cells outlined, and boxes
/// grown by their motion.
constexpr SDL_Color kGridLine{40, 44, 58, 255};
constexpr SDL_Color kGridCellTint{80, 190, 230, 40};
constexpr SDL_Color kGridCellOutline{50, 110, 140, 255};
constexpr SDL_Color kGrownBox{110, 220, 250, 255};
/// Bullets get a light outline, so they can be told from ordinary fast bodies.
constexpr SDL_Color kBulletOutline{255, 255, 255, 255};

constexpr SDL_Color scaled(SDL_Color colour, int percent) {
    return {static_cast<Uint8>(colour.r * percent / 100),
            static_cast<Uint8>(colour.g * percent / 100),
            static_cast<Uint8>(colour.b * percent / 100), colour.a};
}

inline void setColour(SDL_Renderer* renderer, SDL_Color colour) {
    SDL_SetRenderDrawColor(renderer, colour.r, colour.g, colour.b, colour.a);
}

} // namespace jostle::demo
