// shared/glyphs.hpp: a tiny bitmap font, 5 × 7 glyphs for digits, capital letters (small
// ones are drawn as capitals) and a few symbols. The demo draws its text with it
// (demo/font.cpp) and `jostle render` the words of its key (tools/jostle/render.cpp), so
// both pictures read alike.
//
//     const jostle::shared::GlyphRows& rows = jostle::shared::glyphRows('a'); // 'A'
//     if (jostle::shared::glyphPixel(rows, column, row))
//         drawPixel(x + column, y + row);
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

namespace jostle::shared {

/// Glyph size in font pixels, and the advance from one character to the next.
constexpr int kGlyphWidth = 5;
constexpr int kGlyphHeight = 7;
constexpr int kGlyphAdvance = 6;

/// A glyph: 7 rows of 5 bits, the highest bit (0x10) the leftmost pixel.
using GlyphRows = std::array<std::uint8_t, kGlyphHeight>;

/// The glyph of `c`: small letters as capitals, '?' for a character without one.
const GlyphRows& glyphRows(char c);

/// Whether font pixel (column, row), 0 <= column < kGlyphWidth and 0 <= row <
/// kGlyphHeight, is set.
constexpr bool glyphPixel(const GlyphRows& rows, int column, int row) {
    return (rows[static_cast<std::size_t>(row)] & (0x10 >> column)) != 0;
}

/// The width of `text` in font pixels at scale 1 (kGlyphAdvance a character).
constexpr int textAdvance(std::string_view text) {
    return static_cast<int>(text.size()) * kGlyphAdvance;
}

} // namespace jostle::shared
