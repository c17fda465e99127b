// A palette image to draw boxes on: each pixel is an index into a small palette, which is
// what a GIF frame is, and a PNG is made from it by looking the colours up.
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace jostle::cli {

struct Rgb {
    std::uint8_t r = 0;
    std::uint8_t g = 0;
    std::uint8_t b = 0;
    friend constexpr bool operator==(Rgb, Rgb) = default;
};

/// A rectangle of whole pixels: columns x0 .. x1 - 1 and rows y0 .. y1 - 1. Empty when
/// x1 <= x0 or y1 <= y0. It may reach outside the canvas: drawing clips it.
struct PixelRect {
    int x0 = 0;
    int y0 = 0;
    int x1 = 0;
    int y1 = 0;
};

class Canvas {
public:
    /// A width × height image of palette index 0. Both must be > 0.
    Canvas(int width, int height);

    int width() const { return width_; }
    int height() const { return height_; }

    void clear(std::uint8_t index);
    /// Every pixel of `rect` inside the canvas.
    void fill(PixelRect rect, std::uint8_t index);
    /// The 1-pixel border of `rect` (its outermost rows and columns), inside the canvas.
    void outline(PixelRect rect, std::uint8_t index);
    /// A shape within `rect`: the pixels of `rect` whose centre (x + 0.5, y + 0.5)
    /// `inside(x, y)` holds. Its border (those with a neighbour left, right, above or below
    /// that is not in it) in `border`, the rest in `fill`, or left as they are without one.
    /// A shape between pixel centres, none of them in it, still gets the middle pixel of
    /// `rect` (on the canvas), as a box smaller than a pixel does.
    template <class Inside>
    void shape(PixelRect rect, const Inside& inside, std::optional<std::uint8_t> fill,
               std::uint8_t border);
    /// A 1-pixel line from `from` to `to`, in image coordinates (pixel (x, y) covers
    /// [x, x + 1) × [y, y + 1)): the pixel under each of evenly spaced points, one a pixel
    /// along its longer axis, both ends included.
    void line(float fromX, float fromY, float toX, float toY, std::uint8_t index);
    /// `text` in the shared bitmap font (shared/glyphs.hpp: small letters as capitals),
    /// its top left at (x, y), each font pixel a `scale` × `scale` square; clipped.
    /// Returns the x where the next character would go.
    int text(int x, int y, int scale, std::string_view text, std::uint8_t index);

    std::uint8_t at(int x, int y) const { return pixels_[index(x, y)]; }
    /// Row y, left to right.
    std::span<const std::uint8_t> row(int y) const {
        return {pixels_.data() + index(0, y), static_cast<std::size_t>(width_)};
    }

private:
    std::size_t index(int x, int y) const {
        return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
               static_cast<std::size_t>(x);
    }

    int width_;
    int height_;
    std::vector<std::uint8_t> pixels_;
};

template <class Inside>
void Canvas::shape(PixelRect rect, const Inside& inside, std::optional<std::uint8_t> fill,
                   std::uint8_t border) {
    const auto in = [&](int x, int y) {
        return x >= rect.x0 && x < rect.x1 && y >= rect.y0 && y < rect.y1 &&
               inside(x + 0.5, y + 0.5);
    };
    bool any = false;
    for (int y = std::max(rect.y0, 0); y < std::min(rect.y1, height_); ++y)
        for (int x = std::max(rect.x0, 0); x < std::min(rect.x1, width_); ++x) {
            if (!in(x, y))
                continue;
            any = true;
            if (!in(x - 1, y) || !in(x + 1, y) || !in(x, y - 1) || !in(x, y + 1))
                pixels_[index(x, y)] = border;
            else if (fill)
                pixels_[index(x, y)] = *fill;
        }
    // Every centre of `rect` was tried only if it lies wholly on the canvas.
    const bool onCanvas = rect.x0 >= 0 && rect.y0 >= 0 && rect.x1 <= width_ && rect.y1 <= height_;
    if (!any && onCanvas) {
        const int x = rect.x0 + (rect.x1 - rect.x0 - 1) / 2;
        const int y = rect.y0 + (rect.y1 - rect.y0 - 1) / 2;
        this->fill({x, y, x + 1, y + 1}, border);
    }
}

} // namespace jostle::cli
