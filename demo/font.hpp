// The demo's text, because SDL2 draws none: the shared bitmap font (shared/glyphs.hpp,
// which `jostle render`'s key uses too), each font pixel a filled square.
#pragma once

#include "shared/glyphs.hpp"

#include <SDL.h>

#include <string_view>

namespace jostle::demo {

/// Glyph size in font pixels, and the advance from one character to the next.
using shared::kGlyphAdvance;
using shared::kGlyphHeight;
using shared::kGlyphWidth;

/// Draws `text` with its top-left corner at (x, y), each font pixel `scale` screen pixels
/// wide, in the renderer's current colour. Characters without a glyph are drawn as '?'.
/// Returns the x where the next character would go.
int drawText(SDL_Renderer* renderer, int x, int y, int scale, std::string_view text);

/// The width in screen pixels drawText would use.
int textWidth(int scale, std::string_view text);

} // namespace jostle::demo
