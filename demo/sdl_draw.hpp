// The demo's renderer for World::debugDraw (jostle/debug_draw.hpp): the world's shapes,
// contacts and marks drawn with SDL through a pane's View. Every body the demo shows is
// drawn by it: the library decides what is drawn and in what colour, this only how.
#pragma once

#include "view.hpp"

#include "jostle/debug_draw.hpp"

#include <SDL.h>

namespace jostle::demo {

class SdlDraw final : public DebugDraw {
public:
    SdlDraw(SDL_Renderer* renderer, const View& view) : renderer_(renderer), view_(view) {}

    void line(Vec2 from, Vec2 to, Colour colour) override;
    /// Whole pixels, never less than one: a tiny body still shows.
    void box(Vec2 centre, Vec2 half, Colour fill, Colour outline) override;
    /// A fan of triangles from the centre, its arcs a point every 2 pixels or so.
    void roundedBox(Vec2 centre, Vec2 half, float radius, Colour fill, Colour outline) override;
    void triangle(Vec2 a, Vec2 b, Vec2 c, Colour fill, Colour outline) override;
    /// A dot of 3 × 3 pixels, whatever its size.
    void point(Vec2 at, float size, Colour colour) override;

private:
    void setColour(Colour colour);

    SDL_Renderer* renderer_;
    const View& view_;
};

} // namespace jostle::demo
