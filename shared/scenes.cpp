// The shared scenes (scenes.hpp says what each is and the conventions they share).
#include "shared/scenes.hpp"

#include "shared/random.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace jostle::shared {
namespace {

constexpr float kUnitHalf = 0.5f;   ///< half extent of the common box
constexpr float kFriction = 0.5f;   ///< friction of boxes that rest on each other
constexpr float kDt = 1.0f / 60.0f; ///< every scene is meant to run at 60 Hz

void requirePositive(int value, const char* what) {
    if (value < 1)
        throw Error(std::string("shared scenes: ") + what + ": must be >= 1, got " +
                    std::to_string(value));
}

Scene emptyScene(Vec2 gravity) {
    Scene scene;
    scene.world.gravity = gravity;
    scene.dt = kDt;
    return scene;
}

/// Adds a body; its id is its index unless `id` names it.
void add(Scene& scene, const BodyDef& def, std::string id = {}) {
    if (id.empty())
        id = std::to_string(scene.bodies.size());
    scene.bodies.push_back({std::move(id), def});
}

BodyDef staticBox(float x, float y, float hw, float hh, float friction = kFriction) {
    return {.type = BodyType::Static, .x = x, .y = y, .hw = hw, .hh = hh, .friction = friction};
}

/// A pyramid of unit boxes whose base is centred on x = centreX and stands on y = 0.
/// Boxes touch edge to edge, exactly: half extents of 0.5 put every centre on a multiple
/// of 0.5, which floats hold exactly, so no box starts overlapping or floating.
void addPyramid(Scene& scene, float centreX, int rows, const std::string& topId) {
    for (int row = 0; row < rows; ++row) {
        const int boxes = rows - row;
        const float y = -kUnitHalf - static_cast<float>(row);
        for (int i = 0; i < boxes; ++i) {
            const float x = centreX + static_cast<float>(i) - 0.5f * static_cast<float>(boxes - 1);
            const BodyDef box{
                .x = x, .y = y, .hw = kUnitHalf, .hh = kUnitHalf, .friction = kFriction};
            add(scene, box, boxes == 1 ? topId : std::string{});
        }
    }
}

/// A static ground whose top is y = 0, from x = -halfWidth to x = halfWidth.
void addGround(Scene& scene, float halfWidth) {
    add(scene, staticBox(0.0f, 1.0f, halfWidth, 1.0f));
}

} // namespace

Scene pyramid(int rows) {
    requirePositive(rows, "pyramid rows");
    Scene scene = emptyScene({0.0f, kGravity});
    scene.bodies.reserve(static_cast<std::size_t>(rows) * static_cast<std::size_t>(rows + 1) / 2 +
                         1);
    addGround(scene, 0.5f * static_cast<float>(rows) + 10.0f);
    addPyramid(scene, 0.0f, rows, "top");
    return scene;
}

Scene manyPyramids(int count, int rows) {
    requirePositive(count, "manyPyramids count");
    requirePositive(rows, "manyPyramids rows");
    Scene scene = emptyScene({0.0f, kGravity});
    const float pitch = static_cast<float>(rows) + 2.0f; // base width plus a 2-unit gap
    const float span = pitch * static_cast<float>(count);
    addGround(scene, 0.5f * span + 10.0f);
    for (int k = 0; k < count; ++k) {
        const float centreX = -0.5f * span + pitch * (static_cast<float>(k) + 0.5f);
        addPyramid(scene, centreX, rows, "top." + std::to_string(k));
    }
    return scene;
}

Scene rain(int count) {
    requirePositive(count, "rain count");
    constexpr float kMinHalf = 0.5f;
    constexpr float kMaxHalf = 2.0f;
    constexpr float kGap = 0.25f;                     // between boxes at the start
    constexpr float kColumn = 2.0f * kMaxHalf + kGap; // width of a column of boxes
    constexpr float kMeanArea = 4.0f * 1.25f * 1.25f; // 4 E[hw] E[hh]
    constexpr float kPacking = 0.7f;                  // how full the pile will be
    constexpr float kWall = 1.0f;                     // half thickness of the walls

    const float n = static_cast<float>(count);
    const float width = std::max(20.0f, std::round(16.0f * std::sqrt(n)));
    const float pileHeight = n * kMeanArea / (width * kPacking);
    const int columns = std::max(1, static_cast<int>(width / kColumn));
    // The loose columns are taller than the pile will be: walls above both.
    const float columnHeight = n / static_cast<float>(columns) * (2.5f + kGap);
    const float wallHeight = std::ceil(1.2f * std::max(pileHeight, columnHeight) + 4.0f);

    Scene scene = emptyScene({0.0f, kGravity});
    scene.bodies.reserve(static_cast<std::size_t>(count) + 3);
    // Floor (top at y = 0) under the whole container, and two walls standing on it.
    add(scene, staticBox(0.0f, kWall, 0.5f * width + 2.0f * kWall, kWall));
    for (const float side : {-1.0f, 1.0f})
        add(scene,
            staticBox(side * (0.5f * width + kWall), -0.5f * wallHeight, kWall, 0.5f * wallHeight));

    // Boxes in columns inside the container, each column a stack with kGap between
    // boxes, starting 1 unit above the floor: they land within a second or two and settle
    // soon after, so a benchmark reaches the settled pile in a few hundred steps. Box i
    // goes to column i % columns, so the columns fill evenly.
    const float left = -0.5f * static_cast<float>(columns) * kColumn;
    std::vector<float> columnTop(static_cast<std::size_t>(columns), -1.0f);
    Random random(0x5eed0001u);
    for (int i = 0; i < count; ++i) {
        const int column = i % columns;
        const float hw = random.uniform(kMinHalf, kMaxHalf);
        const float hh = random.uniform(kMinHalf, kMaxHalf);
        // A little sideways play inside the column, so the stacks do not land as columns.
        const float play = 0.5f * kColumn - hw - 0.5f * kGap;
        const float x =
            left + kColumn * (static_cast<float>(column) + 0.5f) + random.uniform(-play, play);
        float& top = columnTop[static_cast<std::size_t>(column)];
        const float y = top - hh;
        top -= 2.0f * hh + kGap;
        add(scene, {.x = x, .y = y, .hw = hw, .hh = hh, .friction = kFriction});
    }
    return scene;
}

Scene pile(int count) {
    requirePositive(count, "pile count");
    Scene scene = emptyScene({0.0f, kGravity});
    scene.bodies.reserve(static_cast<std::size_t>(count) + 1);
    addGround(scene, static_cast<float>(count) + 10.0f);
    for (int i = 0; i < count; ++i)
        add(scene,
            {.x = 0.0f, .y = -kUnitHalf, .hw = kUnitHalf, .hh = kUnitHalf, .friction = kFriction});
    return scene;
}

Scene crowdOnFloor(int count, int pieces) {
    requirePositive(count, "crowd count");
    requirePositive(pieces, "floor pieces");
    constexpr float kPitch = 2.0f * kUnitHalf + 0.25f;
    Scene scene = emptyScene({0.0f, kGravity});
    scene.bodies.reserve(static_cast<std::size_t>(count) + static_cast<std::size_t>(pieces));
    const float length = static_cast<float>(count) * kPitch;
    const float piece = length / static_cast<float>(pieces);
    for (int k = 0; k < pieces; ++k)
        add(scene, staticBox(-0.5f * length + piece * (static_cast<float>(k) + 0.5f), 1.0f,
                             0.5f * piece, 1.0f));
    for (int i = 0; i < count; ++i)
        add(scene, {.x = -0.5f * length + kPitch * (static_cast<float>(i) + 0.5f),
                    .y = -kUnitHalf,
                    .hw = kUnitHalf,
                    .hh = kUnitHalf,
                    .friction = kFriction});
    return scene;
}

Scene staticLevel(int tiles) {
    requirePositive(tiles, "level tiles");
    constexpr int kActors = 16;
    constexpr float kActorHalf = 0.4f;
    Scene scene = emptyScene({0.0f, kGravity});
    const float length = static_cast<float>(tiles);
    for (int k = 0; k < tiles; ++k)
        add(scene, staticBox(-0.5f * length + static_cast<float>(k) + kUnitHalf, kUnitHalf,
                             kUnitHalf, kUnitHalf));
    // A wall at each end, so that what slides off turns back.
    for (float side : {-1.0f, 1.0f})
        add(scene, staticBox(side * (0.5f * length + kUnitHalf), -2.0f, kUnitHalf, 3.0f));
    Random random(0x5eed0005u);
    for (int i = 0; i < kActors; ++i)
        add(scene, {.x = -0.5f * length + length * (static_cast<float>(i) + 0.5f) / kActors,
                    .y = -kActorHalf,
                    .hw = kActorHalf,
                    .hh = kActorHalf,
                    .vx = random.sign() * random.uniform(2.0f, 8.0f),
                    .friction = 0.0f});
    return scene;
}

Scene gas(int count) {
    requirePositive(count, "gas count");
    constexpr float kSpacing = 3.0f;   // between centres at the start
    constexpr float kMaxSpeed = 10.0f; // per axis
    constexpr float kWall = 1.0f;      // half thickness of the walls

    const int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count))));
    const float inner = kSpacing * static_cast<float>(side); // inside width and height
    const float half = 0.5f * inner;

    Scene scene = emptyScene({0.0f, 0.0f});
    scene.bodies.reserve(static_cast<std::size_t>(count) + 4);
    // Four walls, closed: the top and bottom ones run under the side walls' ends.
    const auto wall = [](float x, float y, float hw, float hh) {
        BodyDef def = staticBox(x, y, hw, hh, 0.0f);
        def.bounce = 1.0f;
        return def;
    };
    add(scene, wall(0.0f, half + kWall, half + 2.0f * kWall, kWall));
    add(scene, wall(0.0f, -half - kWall, half + 2.0f * kWall, kWall));
    add(scene, wall(-half - kWall, 0.0f, kWall, half));
    add(scene, wall(half + kWall, 0.0f, kWall, half));

    Random random(0x5eed0002u);
    for (int i = 0; i < count; ++i) {
        const float x = -half + kSpacing * (static_cast<float>(i % side) + 0.5f);
        const float y = -half + kSpacing * (static_cast<float>(i / side) + 0.5f);
        const float vx = random.uniform(-kMaxSpeed, kMaxSpeed);
        const float vy = random.uniform(-kMaxSpeed, kMaxSpeed);
        add(scene, {.x = x,
                    .y = y,
                    .hw = kUnitHalf,
                    .hh = kUnitHalf,
                    .vx = vx,
                    .vy = vy,
                    .bounce = 1.0f,
                    .friction = 0.0f});
    }
    return scene;
}

Scene tilemap(int actors) {
    if (actors < 0)
        throw Error("shared scenes: tilemap actors: must be >= 0, got " + std::to_string(actors));
    constexpr int kRows = 40;
    constexpr int kFloorRow = kRows - 1;
    constexpr int kPlatformPitch = 6; // rows from one platform layer to the next
    constexpr int kLayers = 5;
    constexpr float kActorHalf = 0.4f;
    const int columns = std::max(64, actors / 4);

    // The level as a grid of cells, row 0 at the top; cell (c, r) has its centre at
    // (c - columns/2 + 0.5, r - kRows + 0.5), so the floor's top is y = -1.
    std::vector<char> solid(static_cast<std::size_t>(columns) * kRows, 0);
    const auto cell = [&](int c, int r) -> char& {
        return solid[static_cast<std::size_t>(r) * static_cast<std::size_t>(columns) +
                     static_cast<std::size_t>(c)];
    };
    for (int c = 0; c < columns; ++c)
        cell(c, kFloorRow) = 1;
    for (int r = 0; r < kFloorRow; ++r)
        cell(0, r) = cell(columns - 1, r) = 1;
    Random random(0x5eed0003u);
    for (int layer = 1; layer <= kLayers; ++layer) {
        const int row = kFloorRow - layer * kPlatformPitch;
        int c = 2 + random.between(0, 5);
        while (c < columns - 2) {
            const int length = random.between(3, 10);
            for (int k = 0; k < length && c < columns - 2; ++k, ++c)
                cell(c, row) = 1;
            c += random.between(3, 8);
        }
    }

    Scene scene = emptyScene({0.0f, kGravity});
    const auto centre = [&](int c, int r) {
        return Vec2{static_cast<float>(c) - 0.5f * static_cast<float>(columns) + 0.5f,
                    static_cast<float>(r - kRows) + 0.5f};
    };
    for (int r = 0; r < kRows; ++r)
        for (int c = 0; c < columns; ++c)
            if (cell(c, r) != 0) {
                const Vec2 p = centre(c, r);
                add(scene, staticBox(p.x, p.y, kUnitHalf, kUnitHalf));
            }

    // Actors: first one on every free cell that rests on a tile (height 1), then on the
    // cells above those (height 2, 3, ...), until there are enough.
    int placed = 0;
    for (int height = 1; height < kPlatformPitch && placed < actors; ++height)
        for (int r = 0; r + height < kRows && placed < actors; ++r)
            for (int c = 1; c < columns - 1 && placed < actors; ++c) {
                bool free = cell(c, r + height) != 0;
                for (int k = 0; k < height && free; ++k)
                    free = cell(c, r + k) == 0;
                if (!free)
                    continue;
                const Vec2 p = centre(c, r);
                const float vx = random.sign() * random.uniform(2.0f, 8.0f);
                add(scene, {.x = p.x,
                            .y = p.y,
                            .hw = kActorHalf,
                            .hh = kActorHalf,
                            .vx = vx,
                            .friction = 0.0f});
                ++placed;
            }
    if (placed < actors)
        throw Error("shared scenes: tilemap: no room for " + std::to_string(actors) + " actors");
    return scene;
}

} // namespace jostle::shared
