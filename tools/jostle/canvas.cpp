// Filling and outlining clipped rectangles, lines and text: see canvas.hpp.
#include "canvas.hpp"

#include "shared/glyphs.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace jostle::cli {

Canvas::Canvas(int width, int height) : width_(width), height_(height) {
    if (width <= 0 || height <= 0)
        throw std::invalid_argument("Canvas: width and height must be > 0");
    pixels_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0);
}

void Canvas::clear(std::uint8_t index) {
    std::fill(pixels_.begin(), pixels_.end(), index);
}

void Canvas::fill(PixelRect rect, std::uint8_t value) {
    const int x0 = std::max(rect.x0, 0);
    const int x1 = std::min(rect.x1, width_);
    const int y0 = std::max(rect.y0, 0);
    const int y1 = std::min(rect.y1, height_);
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x)
            pixels_[index(x, y)] = value;
}

void Canvas::outline(PixelRect rect, std::uint8_t value) {
    if (rect.x1 <= rect.x0 || rect.y1 <= rect.y0)
        return;
    fill({rect.x0, rect.y0, rect.x1, rect.y0 + 1}, value); // top
    fill({rect.x0, rect.y1 - 1, rect.x1, rect.y1}, value); // bottom
    fill({rect.x0, rect.y0, rect.x0 + 1, rect.y1}, value); // left
    fill({rect.x1 - 1, rect.y0, rect.x1, rect.y1}, value); // right
}

void Canvas::line(float fromX, float fromY, float toX, float toY, std::uint8_t value) {
    const double x0 = static_cast<double>(fromX);
    const double y0 = static_cast<double>(fromY);
    const double dx = static_cast<double>(toX) - x0;
    const double dy = static_cast<double>(toY) - y0;
    // Far beyond the canvas (a body flung away), a line is not worth a point a pixel.
    const double length = std::max(std::abs(dx), std::abs(dy));
    if (!std::isfinite(length))
        return;
    const int steps = static_cast<int>(std::ceil(std::min(length, 1e5)));
    for (int i = 0; i <= steps; ++i) {
        const double t = steps == 0 ? 0.0 : double(i) / double(steps);
        const double x = std::floor(x0 + dx * t);
        const double y = std::floor(y0 + dy * t);
        if (x >= 0 && y >= 0 && x < width_ && y < height_)
            pixels_[index(static_cast<int>(x), static_cast<int>(y))] = value;
    }
}

int Canvas::text(int x, int y, int scale, std::string_view text, std::uint8_t value) {
    for (const char c : text) {
        const shared::GlyphRows& rows = shared::glyphRows(c);
        for (int row = 0; row < shared::kGlyphHeight; ++row)
            for (int column = 0; column < shared::kGlyphWidth; ++column)
                if (shared::glyphPixel(rows, column, row)) {
                    const int left = x + column * scale;
                    const int top = y + row * scale;
                    fill({left, top, left + scale, top + scale}, value);
                }
        x += shared::kGlyphAdvance * scale;
    }
    return x;
}

} // namespace jostle::cli
