// The camera of `jostle render`: which part of the world a frame shows, fixed once at the
// start so that the picture does not jump while bodies move.
//
// The rule (docs/scene-format.md, `jostle render`): take the box that holds every body
// at the start, add a margin of 1/20 of its longer side on each side, and scale it as
// large as fits the image, centred. World y and image y both grow downward.
#pragma once

#include "canvas.hpp"

#include "jostle/math.hpp"

namespace jostle::cli {

/// A box of the world by its corners: x from min.x to max.x, y from min.y to max.y.
struct WorldBox {
    Vec2 min;
    Vec2 max;
};

class Camera {
public:
    /// Fits `bounds` (plus the margin) into a width × height image.
    static Camera fit(WorldBox bounds, int width, int height);

    /// The pixels a box of the world covers: those whose centre lies inside it, but never
    /// none, so that a body smaller than a pixel still shows as one.
    PixelRect toPixels(WorldBox box) const;

    /// Where a point of the world falls in the image, in pixels but not whole ones:
    /// pixel (x, y) covers [x, x + 1) × [y, y + 1).
    Vec2 toImage(Vec2 point) const;

    /// Image pixels per world unit.
    double scale() const { return scale_; }

private:
    Camera(double scale, double offsetX, double offsetY)
        : scale_(scale), offsetX_(offsetX), offsetY_(offsetY) {}

    double scale_;
    double offsetX_; ///< image x = world x × scale + offsetX
    double offsetY_;
};

/// The margin added to each side of the bodies' box: 1/20 of its longer side.
constexpr double kMarginFraction = 1.0 / 20.0;

} // namespace jostle::cli
