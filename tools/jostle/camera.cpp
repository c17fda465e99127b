// Fitting the view and mapping boxes to pixels: see camera.hpp.
#include "camera.hpp"

#include <algorithm>
#include <cmath>

namespace jostle::cli {

namespace {

/// Pixel indices can be far outside the image when a body flies away; clamping keeps
/// them ints (drawing clips what is left). What is not a number is off the image too.
int toPixelIndex(double value) {
    constexpr double kLimit = 1 << 24;
    if (std::isnan(value))
        return -static_cast<int>(kLimit);
    return static_cast<int>(std::clamp(value, -kLimit, kLimit));
}

/// The pixels [first, last) whose centres (i + 0.5) lie in [from, to); at least one.
void span(double from, double to, int& first, int& last) {
    first = toPixelIndex(std::ceil(from - 0.5));
    last = toPixelIndex(std::ceil(to - 0.5));
    if (last <= first) {
        first = toPixelIndex(std::floor((from + to) / 2.0));
        last = first + 1;
    }
}

} // namespace

View View::of(std::span<const WorldBox> boxes) {
    View view;
    // Each box's sides, relative to the origin: a difference of floats, exact or nearly so
    // in double, then a half extent, however small beside the coordinates.
    double minX = -1.0;
    double maxX = 1.0;
    double minY = -1.0;
    double maxY = 1.0;
    if (!boxes.empty()) {
        view.originX_ = static_cast<double>(boxes.front().centre.x);
        view.originY_ = static_cast<double>(boxes.front().centre.y);
        minX = minY = HUGE_VAL;
        maxX = maxY = -HUGE_VAL;
    }
    for (const WorldBox& box : boxes) {
        const double x = static_cast<double>(box.centre.x) - view.originX_;
        const double y = static_cast<double>(box.centre.y) - view.originY_;
        const double hw = static_cast<double>(box.half.x);
        const double hh = static_cast<double>(box.half.y);
        minX = std::min(minX, x - hw);
        maxX = std::max(maxX, x + hw);
        minY = std::min(minY, y - hh);
        maxY = std::max(maxY, y + hh);
    }
    const double margin = std::max(maxX - minX, maxY - minY) * kMarginFraction;
    view.centreX_ = (minX + maxX) / 2.0;
    view.centreY_ = (minY + maxY) / 2.0;
    view.width_ = maxX - minX + 2.0 * margin;
    view.height_ = maxY - minY + 2.0 * margin;
    return view;
}

Camera::Camera(const View& view, int width, int height)
    : view_(view), scale_(std::min(width / view.width(), height / view.height())),
      halfWidth_(width / 2.0), halfHeight_(height / 2.0) {}

PixelRect Camera::toPixels(WorldBox box) const {
    const double x = imageX(static_cast<double>(box.centre.x));
    const double y = imageY(static_cast<double>(box.centre.y));
    const double hw = static_cast<double>(box.half.x) * scale_;
    const double hh = static_cast<double>(box.half.y) * scale_;
    PixelRect rect;
    span(x - hw, x + hw, rect.x0, rect.x1);
    span(y - hh, y + hh, rect.y0, rect.y1);
    return rect;
}

Vec2 Camera::toImage(Vec2 point) const {
    return {static_cast<float>(imageX(static_cast<double>(point.x))),
            static_cast<float>(imageY(static_cast<double>(point.y)))};
}

} // namespace jostle::cli
