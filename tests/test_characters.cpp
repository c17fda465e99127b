// Characters that feel right (docs/characters.md): no ghost walls at ledge corners, no
// hanging on walls, walking on what they stand on at a commanded speed.
#include "jostle/tilemap.hpp"
#include "jostle/world.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace jostle {
namespace {

constexpr float kDt = 1.0f / 60.0f;

// --- Corners ------------------------------------------------------------------------------
//
// A ledge whose top is at y = 0 and whose left face is at x = 0 (y grows downward), built
// three ways; a box (12 × 16) to its left and above its top, rising and moving right: its
// path across the step clears the corner, so nothing may touch it.

enum class Ledge { OneBox, TileMap, SeparateBoxes };

void buildLedge(World& world, Ledge ledge) {
    switch (ledge) {
    case Ledge::OneBox:
        world.createBody({.type = BodyType::Static, .x = 24, .y = 8, .hw = 24, .hh = 8});
        break;
    case Ledge::TileMap:
        createTileMap(world, {.x = 0, .y = 0, .tile = 16, .rows = {"###", "###"}});
        break;
    case Ledge::SeparateBoxes:
        for (int i = 0; i < 3; ++i)
            world.createBody(
                {.type = BodyType::Static, .x = 8.0f + 16.0f * float(i), .y = 8, .hw = 8, .hh = 8});
        break;
    }
}

const char* nameOf(Ledge ledge) {
    return ledge == Ledge::OneBox ? "one box" : ledge == Ledge::TileMap ? "tile map" : "boxes";
}

TEST(Corners, ABoxRisingPastALedgeCornerKeepsItsVelocity) {
    // The case of the issue: 1.25 from the face, 0.33 above the top, at (150, -310).
    for (Ledge ledge : {Ledge::OneBox, Ledge::TileMap, Ledge::SeparateBoxes})
        for (float gapX : {0.2f, 1.25f, 3.0f, 6.0f})
            for (float gapY : {0.2f, 0.33f, 1.0f, 4.0f})
                for (float vx : {60.0f, 150.0f, 400.0f})
                    for (float vy : {-50.0f, -310.0f, -700.0f})
                        for (float g : {0.0f, 800.0f}) {
                            World world(WorldDef{.gravity = {0, g}});
                            buildLedge(world, ledge);
                            const BodyId box = world.createBody({.x = -gapX - 6,
                                                                 .y = -gapY - 8,
                                                                 .hw = 6,
                                                                 .hh = 8,
                                                                 .vx = vx,
                                                                 .vy = vy});
                            world.step(kDt);
                            // Gravity acts for the step: vy + g dt; nothing else.
                            const Vec2 v = world.velocity(box);
                            const Touching t = world.touching(box);
                            EXPECT_EQ(v.x, vx) << nameOf(ledge) << " gap " << gapX << ", " << gapY
                                               << " at " << vx << ", " << vy << " g " << g;
                            EXPECT_FLOAT_EQ(v.y, vy + g * kDt);
                            EXPECT_FALSE(t.wallRight || t.wallLeft || t.floor || t.ceiling);
                        }
}

TEST(Corners, ABoxRisingAlongALedgeOfSeparateBoxesIsNeverStopped) {
    // Without gravity the box rises for good, 0.33 above a floor of boxes and moving
    // along it past every seam: its velocity never changes.
    for (Ledge ledge : {Ledge::TileMap, Ledge::SeparateBoxes}) {
        World world(WorldDef{.gravity = {0, 0}});
        buildLedge(world, ledge);
        const BodyId box =
            world.createBody({.x = -7, .y = -8.33f, .hw = 6, .hh = 8, .vx = 200, .vy = -20});
        for (int step = 0; step < 30; ++step) {
            world.step(kDt);
            ASSERT_EQ(world.velocity(box), (Vec2{200, -20})) << nameOf(ledge) << " step " << step;
        }
    }
}

TEST(Corners, ABoxFallingOntoALedgeCornerLandsOnItsTop) {
    // 1.25 from the face and 2 above the top, moving at (600, 400): its path is over the
    // top after 1.25 / 600 = 2.1 ms, before it comes down to the top's level (2 / 400 =
    // 5 ms), so it lands on the top. By gaps alone (x is the larger) it was a wall.
    World world(WorldDef{.gravity = {0, 0}});
    buildLedge(world, Ledge::OneBox);
    const BodyId lands =
        world.createBody({.x = -1.25f - 6, .y = -2 - 8, .hw = 6, .hh = 8, .vx = 600, .vy = 400});
    world.step(kDt);
    EXPECT_TRUE(world.touching(lands).floor);
    EXPECT_FALSE(world.touching(lands).wallRight);
    // A speculative contact: it closes its gap of 2 in the step (2 / dt = 120) and no more,
    // its bottom on the top.
    EXPECT_FLOAT_EQ(world.velocity(lands).y, 120.0f);
    EXPECT_NEAR(world.position(lands).y, -8.0f, 1e-3f);
}

} // namespace
} // namespace jostle
