// Drawing the broadphase picture: see draw_grid_picture.hpp.
#include "draw_grid_picture.hpp"

#include "palette.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <tuple>
#include <vector>

namespace jostle::demo {

namespace {

/// Lines closer than this many pixels would fill the pane rather than show cells.
constexpr float kMinCellPixels = 6.0f;
/// A grown box is outlined only where it is this many pixels larger than its body on
/// some side: at rest it is the body itself, and an outline would only hide the body's.
constexpr float kMinGrowthPixels = 2.0f;

/// A cell's index along one axis: floor(value / cell), kept within what an int64 holds.
std::int64_t cellIndex(float value, double cell) {
    constexpr double kLimit = 1e15;
    return std::int64_t(std::clamp(std::floor(double(value) / cell), -kLimit, kLimit));
}

SDL_Rect cellRect(const View& view, std::int64_t x, std::int64_t y, double cell) {
    const double half = cell / 2.0;
    return view.toScreen({float(double(x) * cell + half), float(double(y) * cell + half)},
                         {float(half), float(half)});
}

void drawLines(SDL_Renderer* renderer, const View& view, double cell) {
    if (!std::isfinite(cell) || float(cell) * view.scale() < kMinCellPixels)
        return;
    const SDL_Rect& screen = view.screen();
    const Vec2 from = view.toWorld(screen.x, screen.y);
    const Vec2 to = view.toWorld(screen.x + screen.w, screen.y + screen.h);
    setColour(renderer, kGridLine);
    for (std::int64_t i = cellIndex(from.x, cell); i <= cellIndex(to.x, cell) + 1; ++i) {
        const int x = view.toScreen({float(double(i) * cell), 0.0f}).x;
        SDL_RenderDrawLine(renderer, x, screen.y, x, screen.y + screen.h - 1);
    }
    for (std::int64_t i = cellIndex(from.y, cell); i <= cellIndex(to.y, cell) + 1; ++i) {
        const int y = view.toScreen({0.0f, float(double(i) * cell)}).y;
        SDL_RenderDrawLine(renderer, screen.x, y, screen.x + screen.w - 1, y);
    }
}

} // namespace

void drawGridPicture(SDL_Renderer* renderer, const GridPicture& picture, const View& view) {
    if (picture.boxes.empty())
        return;
    // Each box is filed in one cell of its level, the one that holds its min corner.
    // Several boxes share a cell: each cell is drawn once, or the tints would add up.
    std::vector<std::tuple<int, std::int64_t, std::int64_t>> cells;
    cells.reserve(picture.boxes.size());
    for (const GridBox& box : picture.boxes) {
        const double cell = picture.cellSize(box.level);
        if (std::isfinite(cell))
            cells.emplace_back(box.level, cellIndex(box.bounds.min.x, cell),
                               cellIndex(box.bounds.min.y, cell));
    }
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());

    SDL_SetRenderDrawBlendMode(renderer, SDL_BLENDMODE_BLEND);
    setColour(renderer, kGridCellTint);
    for (const auto& [level, x, y] : cells)
        if (level == picture.mainLevel) {
            const SDL_Rect rect = cellRect(view, x, y, picture.cellSize(level));
            SDL_RenderFillRect(renderer, &rect);
        }
    SDL_SetRenderDrawBlendMode(renderer, SDL_BLENDMODE_NONE);

    drawLines(renderer, view, picture.cellSize(picture.mainLevel));

    setColour(renderer, kGridCellOutline);
    for (const auto& [level, x, y] : cells)
        if (level != picture.mainLevel) {
            const SDL_Rect rect = cellRect(view, x, y, picture.cellSize(level));
            SDL_RenderDrawRect(renderer, &rect);
        }

    setColour(renderer, kGrownBox);
    for (const GridBox& box : picture.boxes) {
        if (std::max(box.growth.x, box.growth.y) * view.scale() < kMinGrowthPixels)
            continue;
        const Vec2 centre = (box.bounds.min + box.bounds.max) * 0.5f;
        const SDL_Rect rect = view.toScreen(centre, (box.bounds.max - box.bounds.min) * 0.5f);
        SDL_RenderDrawRect(renderer, &rect);
    }
}

} // namespace jostle::demo
