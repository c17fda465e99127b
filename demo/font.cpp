// Drawing text with the shared font: see font.hpp.
#include "font.hpp"

#include <vector>

namespace jostle::demo {

int drawText(SDL_Renderer* renderer, int x, int y, int scale, std::string_view text) {
    // One batch of rectangles per string: far fewer renderer calls than one per pixel.
    std::vector<SDL_Rect> pixels;
    for (char c : text) {
        const shared::GlyphRows& rows = shared::glyphRows(c);
        for (int row = 0; row < kGlyphHeight; ++row)
            for (int column = 0; column < kGlyphWidth; ++column)
                if (shared::glyphPixel(rows, column, row))
                    pixels.push_back({x + column * scale, y + row * scale, scale, scale});
        x += kGlyphAdvance * scale;
    }
    if (!pixels.empty())
        SDL_RenderFillRects(renderer, pixels.data(), static_cast<int>(pixels.size()));
    return x;
}

int textWidth(int scale, std::string_view text) {
    return shared::textAdvance(text) * scale;
}

} // namespace jostle::demo
