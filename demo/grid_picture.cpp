// The broadphase picture: see grid_picture.hpp (drawn by draw_grid_picture.cpp). The rule mirrored
// here is the one docs/broadphase.md gives ("Levels by size"); the numbers (1.25, 90%, one merge at
// most, 64 levels, the margin of one part in a million) are the documented ones.
#include "grid_picture.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace jostle::demo {

namespace {

/// Level 0's cells are this many times the smallest box.
constexpr double kLevelZeroSpare = 1.25;
/// Levels 0 and 1 are merged when together they hold at least this share of the boxes.
constexpr double kMergedShare = 0.9;
/// A box goes to the first level whose cells are at least its size times this.
constexpr double kSizeMargin = 1.0 + 1.0 / (1 << 20);

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

} // namespace jostle::demo
