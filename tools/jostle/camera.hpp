// The camera of `jostle render`: which part of the world a frame shows, fixed once at the
// start so that the picture does not jump while bodies move.
//
// The rule (docs/scene-format.md, `jostle render`): take the box that holds every body
// at the start, add a margin of 1/20 of its longer side on each side, and scale it as
// large as fits the image, centred. World y and image y both grow downward.
//
// Any scene of the world's range (magnitudes 1e-9 to 1e9) has a view, drawn as precisely
// as the bodies in it: coordinates are taken in double, relative to a point of the scene
// (a body's centre), so that a body 1e-9 across at x = 1e9, where floats are 64 apart,
// still fills a view of its own size.
#pragma once

#include "canvas.hpp"

#include "jostle/math.hpp"

#include <span>

namespace jostle::cli {

/// A box of the world as the world gives it: its centre and half extents.
struct WorldBox {
    Vec2 centre;
    Vec2 half;
};

/// What the camera shows: the box that holds some boxes, with its margin.
class View {
public:
    /// The view of `boxes`; of a 2 × 2 box around the origin when there are none.
    static View of(std::span<const WorldBox> boxes);

    /// The view's size in world units, the margin included; both > 0.
    double width() const { return width_; }
    double height() const { return height_; }

private:
    friend class Camera;
    double originX_ = 0.0; ///< the point of the world the others are relative to
    double originY_ = 0.0;
    double centreX_ = 0.0; ///< the view's centre, relative to the origin
    double centreY_ = 0.0;
    double width_ = 0.0;
    double height_ = 0.0;
};

class Camera {
public:
    /// Fits `view` into a width × height image.
    Camera(const View& view, int width, int height);

    /// The pixels a box of the world covers: those whose centre lies inside it, but never
    /// none, so that a body smaller than a pixel still shows as one.
    PixelRect toPixels(WorldBox box) const;

    /// Where a point of the world falls in the image, in pixels but not whole ones:
    /// pixel (x, y) covers [x, x + 1) × [y, y + 1).
    Vec2 toImage(Vec2 point) const;

    /// Image pixels per world unit.
    double scale() const { return scale_; }

private:
    double imageX(double x) const {
        return ((x - view_.originX_) - view_.centreX_) * scale_ + halfWidth_;
    }
    double imageY(double y) const {
        return ((y - view_.originY_) - view_.centreY_) * scale_ + halfHeight_;
    }

    View view_;
    double scale_;
    double halfWidth_; ///< of the image, in pixels
    double halfHeight_;
};

/// The margin added to each side of the bodies' box: 1/20 of its longer side.
constexpr double kMarginFraction = 1.0 / 20.0;

} // namespace jostle::cli
