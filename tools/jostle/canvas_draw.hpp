// `jostle render`'s renderer for World::debugDraw (jostle/debug_draw.hpp): the library says
// what is drawn and in which colour, this draws it on a palette Canvas through the Camera,
// each colour the palette's entry of the same value.
#pragma once

#include "camera.hpp"
#include "canvas.hpp"

#include "jostle/debug_draw.hpp"

#include <cstdint>
#include <span>

namespace jostle::cli {

class CanvasDraw final : public DebugDraw {
public:
    /// Draws on `canvas`, whose palette is `palette`: every colour drawn must be one of it.
    CanvasDraw(Canvas& canvas, const Camera& camera, std::span<const Rgb> palette)
        : canvas_(canvas), camera_(camera), palette_(palette) {}

    void line(Vec2 from, Vec2 to, Colour colour) override;
    /// The pixels whose centre is inside, but never none (Camera::toPixels).
    void box(Vec2 centre, Vec2 half, Colour fill, Colour outline) override;
    void roundedBox(Vec2 centre, Vec2 half, float radius, Colour fill, Colour outline) override;
    void triangle(Vec2 a, Vec2 b, Vec2 c, Colour fill, Colour outline) override;
    /// A dot of 3 × 3 pixels, whatever its size.
    void point(Vec2 at, float size, Colour colour) override;

    /// The palette's entry of `colour` (opacity aside); the last entry for one it lacks.
    std::uint8_t indexOf(Colour colour) const;

private:
    Canvas& canvas_;
    const Camera& camera_;
    std::span<const Rgb> palette_;
};

} // namespace jostle::cli
