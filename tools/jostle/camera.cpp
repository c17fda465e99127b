// Fitting the view and mapping boxes to pixels: see camera.hpp.
#include "camera.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace jostle::cli {

namespace {

/// Pixel indices can be far outside the image when a body flies away; clamping keeps
/// them ints (drawing clips what is left).
int toPixelIndex(double value) {
    constexpr double kLimit = 1 << 24;
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

Camera Camera::fit(WorldBox bounds, int width, int height) {
    const double minX = double(bounds.min.x);
    const double minY = double(bounds.min.y);
    double spanX = static_cast<double>(bounds.max.x) - minX;
    double spanY = static_cast<double>(bounds.max.y) - minY;
    const double margin = std::max(spanX, spanY) * kMarginFraction;
    spanX += 2.0 * margin;
    spanY += 2.0 * margin;
    // Degenerate bounds (no bodies) cannot happen with a margin, as bodies have a size;
    // but a camera must never divide by zero.
    const double tiny = double(std::numeric_limits<float>::min());
    const double scale = std::min(width / std::max(spanX, tiny), height / std::max(spanY, tiny));
    const double centreX = minX + (spanX / 2.0 - margin);
    const double centreY = minY + (spanY / 2.0 - margin);
    return Camera(scale, width / 2.0 - centreX * scale, height / 2.0 - centreY * scale);
}

PixelRect Camera::toPixels(WorldBox box) const {
    const auto imageX = [this](float x) { return static_cast<double>(x) * scale_ + offsetX_; };
    const auto imageY = [this](float y) { return static_cast<double>(y) * scale_ + offsetY_; };
    PixelRect rect;
    span(imageX(box.min.x), imageX(box.max.x), rect.x0, rect.x1);
    span(imageY(box.min.y), imageY(box.max.y), rect.y0, rect.y1);
    return rect;
}

Vec2 Camera::toImage(Vec2 point) const {
    return {static_cast<float>(static_cast<double>(point.x) * scale_ + offsetX_),
            static_cast<float>(static_cast<double>(point.y) * scale_ + offsetY_)};
}

} // namespace jostle::cli
