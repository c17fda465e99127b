// A tiny bitmap font, because SDL2 draws no text: 5 × 7 glyphs for digits, capital
// letters (small ones are drawn as capitals) and a few symbols, each pixel a filled square.
#pragma once

#include <SDL.h>

#include <string_view>

namespace jostle::demo {

/// Glyph size in font pixels, and the advance from one character to the next.
constexpr int kGlyphWidth = 5;
constexpr int kGlyphHeight = 7;
constexpr int kGlyphAdvance = 6;

/// Draws `text` with its top-left corner at (x, y), each font pixel `scale` screen pixels
/// wide, in the renderer's current colour. Characters without a glyph are drawn as '?'.
/// Returns the x where the next character would go.
int drawText(SDL_Renderer* renderer, int x, int y, int scale, std::string_view text);

/// The width in screen pixels drawText would use.
int textWidth(int scale, std::string_view text);

} // namespace jostle::demo
