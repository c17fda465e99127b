// The broadphase picture: see grid_picture.hpp. The rule mirrored here is the one
// docs/broadphase.md gives ("Levels by size"); the numbers (1.25, 90%, one merge at
// most, 64 levels, the margin of one part in a million) are the documented ones.
#include "grid_picture.hpp"

#include "palette.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

namespace jostle::demo {

namespace {

/// Level 0's cells are this many times the smallest box.
constexpr double kLevelZeroSpare = 1.25;
/// Levels 0 and 1 are merged when together they hold at least this share of the boxes.
constexpr double kMergedShare = 0.9;
/// A box goes to the first level whose cells are at least its size times this.
constexpr double kSizeMargin = 1.0 + 1.0 / (1 << 20);
/// Lines closer than this many pixels would fill the pane rather than show cells.
constexpr float kMinCellPixels = 6.0f;
/// A grown box is outlined only where it is this many pixels larger than its body on
/// some side: at rest it is the body itself, and an outline would only hide the body's.
constexpr float kMinGrowthPixels = 2.0f;

double sizeOf(const WorldBox& box) {
    return std::max(double(box.max.x - box.min.x), double(box.max.y - box.min.y));
}

/// The box of a body, grown on every side by `growth`.
WorldBox boxOf(const World& world, BodyId body, Vec2 growth) {
    const Vec2 centre = world.position(body);
    const Vec2 half = world.halfExtents(body) + growth;
    return {centre - half, centre + half};
}

/// The boxes of the grid the last step used, by the world's rules (docs/broadphase.md,
/// "How the world uses it"). Kinematic bodies have a grid of their own in the classic
/// model, left out of this picture.
std::vector<WorldBox> gridBoxes(const World& world, float dt, std::string& name,
                                std::vector<Vec2>& growths) {
    std::vector<WorldBox> boxes;
    const bool physical = world.solver() == Solver::Physical;
    for (const bool moving : {true, false}) {
        name = physical ? (moving ? "moving" : "resting") : (moving ? "dynamic" : "static");
        for (BodyId body : world.bodies()) {
            const BodyType type = world.type(body);
            bool inGrid = false;
            if (physical)
                inGrid = (type != BodyType::Static && world.isAwake(body)) == moving;
            else
                inGrid = moving ? type == BodyType::Dynamic : type == BodyType::Static;
            if (!inGrid)
                continue;
            // The physical model grows a moving box by the distance its velocity carries
            // it in a step; the classic model files its dynamic bodies as they are.
            const Vec2 velocity = world.velocity(body);
            const Vec2 growth = physical && moving
                                    ? Vec2{std::abs(velocity.x) * dt, std::abs(velocity.y) * dt}
                                    : Vec2{};
            boxes.push_back(boxOf(world, body, growth));
            growths.push_back(growth);
        }
        // The grid rebuilt every step while anything moves; else the one of what rests.
        if (!boxes.empty())
            break;
    }
    return boxes;
}

/// 0 or 1: by how many doublings level 0's cells grow so that it holds most boxes.
int mergedLevels(const std::vector<WorldBox>& boxes, double base) {
    std::size_t first = 0, second = 0;
    for (const WorldBox& box : boxes) {
        const double size = sizeOf(box);
        first += size <= base ? 1 : 0;
        second += size > base && size <= 2.0 * base ? 1 : 0;
    }
    const double most = kMergedShare * double(boxes.size());
    if (double(first) >= most)
        return 0;
    return double(first + second) >= most ? 1 : 0;
}

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

double GridPicture::cellSize(int level) const {
    return level >= kGridLevels - 1 ? std::numeric_limits<double>::infinity()
                                    : std::ldexp(levelZero, level);
}

GridPicture pictureGrid(const World& world, float dt) {
    GridPicture picture;
    std::vector<Vec2> growths;
    const std::vector<WorldBox> boxes = gridBoxes(world, dt, picture.name, growths);
    if (boxes.empty())
        return picture;

    double smallest = std::numeric_limits<double>::infinity(), largest = 0.0;
    for (const WorldBox& box : boxes) {
        smallest = std::min(smallest, sizeOf(box));
        largest = std::max(largest, sizeOf(box));
    }
    const double tiny = double(std::numeric_limits<float>::min());
    double base = std::max(smallest, tiny) * kLevelZeroSpare;
    // If 63 doublings cannot reach the largest box, level 0 is made coarser.
    base = std::max(base, std::ldexp(std::max(largest, tiny), -(kGridLevels - 2)));
    picture.levelZero = std::ldexp(base, mergedLevels(boxes, base));

    std::vector<std::size_t> counts(kGridLevels, 0);
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        const double size = sizeOf(boxes[i]) * kSizeMargin;
        int level = 0;
        while (level < kGridLevels - 1 && picture.cellSize(level) < size)
            ++level;
        picture.boxes.push_back({boxes[i], growths[i], level});
        ++counts[std::size_t(level)];
    }
    const auto most = std::max_element(counts.begin(), counts.end());
    picture.mainLevel = int(most - counts.begin());
    picture.inMainLevel = *most;
    return picture;
}

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
