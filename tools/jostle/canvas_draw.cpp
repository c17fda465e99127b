// Debug drawing on a palette canvas: see canvas_draw.hpp.
#include "canvas_draw.hpp"

#include "shared/drawn_shape.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>

namespace jostle::cli {

std::uint8_t CanvasDraw::indexOf(Colour colour) const {
    const Rgb wanted{colour.r, colour.g, colour.b};
    const auto found = std::find(palette_.begin(), palette_.end(), wanted);
    const auto index = found != palette_.end() ? found - palette_.begin()
                                               : static_cast<std::ptrdiff_t>(palette_.size()) - 1;
    return static_cast<std::uint8_t>(index);
}

void CanvasDraw::line(Vec2 from, Vec2 to, Colour colour) {
    const Vec2 a = camera_.toImage(from), b = camera_.toImage(to);
    canvas_.line(a.x, a.y, b.x, b.y, indexOf(colour));
}

void CanvasDraw::box(Vec2 centre, Vec2 half, Colour fill, Colour outline) {
    const PixelRect rect = camera_.toPixels({centre, half});
    if (fill.a != 0)
        canvas_.fill(rect, indexOf(fill));
    canvas_.outline(rect, indexOf(outline));
}

void CanvasDraw::roundedBox(Vec2 centre, Vec2 half, float radius, Colour fill, Colour outline) {
    const shared::DrawnShape shape{shared::DrawnKind::Rounded, centre, half, radius, {}};
    const shared::DrawnShape seen =
        shape.mapped(camera_.toImage(centre), static_cast<float>(camera_.scale()));
    const auto inside = [&](double x, double y) {
        return seen.contains({static_cast<float>(x), static_cast<float>(y)});
    };
    canvas_.shape(camera_.toPixels({centre, half}), inside,
                  fill.a != 0 ? std::optional(indexOf(fill)) : std::nullopt, indexOf(outline));
}

void CanvasDraw::triangle(Vec2 a, Vec2 b, Vec2 c, Colour fill, Colour outline) {
    const Vec2 p[] = {camera_.toImage(a), camera_.toImage(b), camera_.toImage(c)};
    // Inside: on the same side of all three edges (or on one), whichever way round they go.
    const auto side = [&](int i, double x, double y) {
        const Vec2 from = p[i], to = p[(i + 1) % 3];
        const double fx = double(from.x), fy = double(from.y), tx = double(to.x), ty = double(to.y);
        return (tx - fx) * (y - fy) - (ty - fy) * (x - fx);
    };
    const auto inside = [&](double x, double y) {
        const double s0 = side(0, x, y), s1 = side(1, x, y), s2 = side(2, x, y);
        return (s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0);
    };
    const Vec2 low{std::min({a.x, b.x, c.x}), std::min({a.y, b.y, c.y})};
    const Vec2 high{std::max({a.x, b.x, c.x}), std::max({a.y, b.y, c.y})};
    canvas_.shape(camera_.toPixels({(low + high) * 0.5f, (high - low) * 0.5f}), inside,
                  fill.a != 0 ? std::optional(indexOf(fill)) : std::nullopt, indexOf(outline));
}

void CanvasDraw::point(Vec2 at, float, Colour colour) {
    // A point far off the image still makes whole pixels, clipped by the canvas.
    const Vec2 p = camera_.toImage(at);
    const auto pixel = [](float v) {
        return static_cast<int>(std::clamp(std::floor(v), -1e8f, 1e8f));
    };
    const int x = pixel(p.x), y = pixel(p.y);
    canvas_.fill({x - 1, y - 1, x + 2, y + 2}, indexOf(colour));
}

} // namespace jostle::cli
