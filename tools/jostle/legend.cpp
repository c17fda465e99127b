// Laying out and drawing the key: see legend.hpp.
#include "legend.hpp"

#include "shared/glyphs.hpp"

#include <algorithm>

namespace jostle::cli {

namespace {

// Measures in font pixels, so that the key keeps its shape at either size.
constexpr int kSwatch = shared::kGlyphHeight; ///< a swatch is a square as tall as a letter
constexpr int kSwatchGap = 3;                 ///< between a swatch and its word
constexpr int kEntryGap = 12;                 ///< between one entry's word and the next swatch
constexpr int kMargin = 5;                    ///< around the rows, inside the band
constexpr int kRowGap = 4;
constexpr int kLargeScale = 2;

/// An entry's width at scale 1: its swatch, the gap, its word (without the space after
/// the last letter).
int entryWidth(const LegendEntry& entry) {
    return kSwatch + kSwatchGap + shared::textAdvance(entry.word) - 1;
}

} // namespace

Legend::Legend(std::vector<LegendEntry> entries, int width) {
    int oneRow = 2 * kMargin;
    for (std::size_t i = 0; i < entries.size(); ++i)
        oneRow += entryWidth(entries[i]) + (i > 0 ? kEntryGap : 0);
    scale_ = oneRow * kLargeScale <= width ? kLargeScale : 1;
    int x = kMargin * scale_;
    int row = 0;
    for (LegendEntry& entry : entries) {
        const int entryPixels = entryWidth(entry) * scale_;
        // A new row when this entry would cross the right margin, unless the row is empty
        // (an entry wider than the image is cut at its edge).
        if (x > kMargin * scale_ && x + entryPixels > width - kMargin * scale_) {
            x = kMargin * scale_;
            ++row;
        }
        placed_.push_back({std::move(entry), x, row});
        x += entryPixels + kEntryGap * scale_;
    }
    rows_ = placed_.empty() ? 0 : row + 1;
}

int Legend::height() const {
    if (rows_ == 0)
        return 0;
    return 1 + (2 * kMargin + rows_ * kSwatch + (rows_ - 1) * kRowGap) * scale_;
}

void Legend::draw(Canvas& canvas, int top, LegendColours colours) const {
    if (rows_ == 0)
        return;
    canvas.fill({0, top, canvas.width(), canvas.height()}, colours.background);
    canvas.fill({0, top, canvas.width(), top + 1}, colours.line);
    for (const Placed& placed : placed_) {
        const int y = top + 1 + (kMargin + placed.row * (kSwatch + kRowGap)) * scale_;
        const PixelRect swatch{placed.x, y, placed.x + kSwatch * scale_, y + kSwatch * scale_};
        if (placed.entry.fill)
            canvas.fill(swatch, *placed.entry.fill);
        canvas.outline(swatch, placed.entry.outline);
        canvas.text(swatch.x1 + kSwatchGap * scale_, y, scale_, placed.entry.word, colours.text);
    }
}

} // namespace jostle::cli
