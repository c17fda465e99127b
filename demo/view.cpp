// Fitting a world box into a pane and mapping between the two: see view.hpp.
#include "view.hpp"

#include <algorithm>
#include <cmath>

namespace jostle::demo {

namespace {

constexpr float kMarginFraction = 1.0f / 20.0f;

/// Bodies flung far away must not overflow an int: drawing clips what is left.
int toPixel(float value) {
    constexpr float kLimit = 1 << 24;
    return static_cast<int>(std::clamp(std::round(value), -kLimit, kLimit));
}

} // namespace

View View::fit(WorldBox box, SDL_Rect screen) {
    float spanX = box.max.x - box.min.x;
    float spanY = box.max.y - box.min.y;
    const float margin = std::max(spanX, spanY) * kMarginFraction;
    spanX += 2.0f * margin;
    spanY += 2.0f * margin;
    View view;
    view.screen_ = screen;
    view.scale_ = std::min(static_cast<float>(screen.w) / std::max(spanX, 1e-6f),
                           static_cast<float>(screen.h) / std::max(spanY, 1e-6f));
    const float centreX = (box.min.x + box.max.x) / 2.0f;
    const float centreY = (box.min.y + box.max.y) / 2.0f;
    view.offsetX_ =
        static_cast<float>(screen.x) + static_cast<float>(screen.w) / 2.0f - centreX * view.scale_;
    view.offsetY_ =
        static_cast<float>(screen.y) + static_cast<float>(screen.h) / 2.0f - centreY * view.scale_;
    return view;
}

SDL_Rect View::toScreen(Vec2 centre, Vec2 half) const {
    const int x0 = toPixel((centre.x - half.x) * scale_ + offsetX_);
    const int y0 = toPixel((centre.y - half.y) * scale_ + offsetY_);
    const int x1 = toPixel((centre.x + half.x) * scale_ + offsetX_);
    const int y1 = toPixel((centre.y + half.y) * scale_ + offsetY_);
    return {x0, y0, std::max(1, x1 - x0), std::max(1, y1 - y0)};
}

SDL_Point View::toScreen(Vec2 point) const {
    return {toPixel(point.x * scale_ + offsetX_), toPixel(point.y * scale_ + offsetY_)};
}

SDL_FPoint View::toScreenExact(Vec2 point) const {
    return {point.x * scale_ + offsetX_, point.y * scale_ + offsetY_};
}

Vec2 View::toWorld(int x, int y) const {
    return {(static_cast<float>(x) - offsetX_) / scale_,
            (static_cast<float>(y) - offsetY_) / scale_};
}

bool View::contains(int x, int y) const {
    const SDL_Point point{x, y};
    return SDL_PointInRect(&point, &screen_) == SDL_TRUE;
}

} // namespace jostle::demo
