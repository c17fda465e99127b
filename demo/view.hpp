// How a pane of the window shows a box of a world: the scale and offset that fit the box,
// with a margin, into the pane's pixels, and back again for the mouse.
#pragma once

#include "world_box.hpp"

#include <SDL.h>

namespace jostle::demo {

class View {
public:
    /// Fits `box` plus a margin of 1/20 of its longer side into `screen`, centred, at the
    /// same scale along both axes (the rule of `jostle render`'s camera).
    static View fit(WorldBox box, SDL_Rect screen);

    /// The pixels a box of the world covers; never less than one pixel, so that a tiny
    /// body still shows.
    SDL_Rect toScreen(Vec2 centre, Vec2 half) const;
    SDL_Point toScreen(Vec2 point) const;
    /// Where a point falls on the screen, not rounded to a pixel: for shapes drawn with
    /// SDL's float functions.
    SDL_FPoint toScreenExact(Vec2 point) const;
    Vec2 toWorld(int x, int y) const;
    bool contains(int x, int y) const;

    const SDL_Rect& screen() const { return screen_; }
    /// Pixels per world unit.
    float scale() const { return scale_; }

private:
    SDL_Rect screen_{};
    float scale_ = 1.0f;
    float offsetX_ = 0.0f; ///< screen x = world x × scale + offsetX
    float offsetY_ = 0.0f;
};

} // namespace jostle::demo
