// `jostle render --legend`: a key to the picture's colours, in a band under the scene. Each
// entry is a swatch drawn as a body of that kind is (filled and outlined, or outlined only
// for a sensor) and its word. The rule is in docs/scene-format.md, `jostle render`.
#pragma once

#include "canvas.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace jostle::cli {

struct LegendEntry {
    std::optional<std::uint8_t> fill; ///< none: outlined only, as a sensor is
    std::uint8_t outline = 0;
    std::string word;
};

/// The palette indices of the band itself.
struct LegendColours {
    std::uint8_t background = 0;
    std::uint8_t line = 0; ///< the line between the scene and the band
    std::uint8_t text = 0;
};

/// The entries laid out left to right across an image `width` pixels wide: at twice the
/// font's size when they fit in one row that way, else at its size, in as many rows as
/// they need.
class Legend {
public:
    Legend(std::vector<LegendEntry> entries, int width);

    /// The band's height in pixels, the line along its top included.
    int height() const;
    /// Draws the band from row `top` to the bottom of the canvas, over whatever is there
    /// (a body that left the view downwards).
    void draw(Canvas& canvas, int top, LegendColours colours) const;

private:
    struct Placed {
        LegendEntry entry;
        int x = 0;   ///< the swatch's left edge, in pixels
        int row = 0; ///< counted from 0
    };

    std::vector<Placed> placed_;
    int scale_ = 1;
    int rows_ = 0;
};

} // namespace jostle::cli
