// A palette image to draw boxes on: each pixel is an index into a small palette, which is
// what a GIF frame is, and a PNG is made from it by looking the colours up.
#pragma once

#include <cstdint>
#include <span>
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

} // namespace jostle::cli
