// A platformer character built on jostle alone, end to end: it walks a tile floor, jumps
// up through a one-way platform and drops back through it, rides a lift, slides down a
// tiled wall, and looks at the world with queries. Each feature has its own tests; this
// one checks that they work together, as a game uses them.
#include "jostle/fixed_step.hpp"
#include "jostle/query.hpp"
#include "jostle/tilemap.hpp"
#include "jostle/world.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace jostle {
namespace {

constexpr float kG = 800.0f;
constexpr float kDt = 1.0f / 60.0f;
constexpr float kTile = 16.0f;

// 40 tiles wide, 20 high; y grows downward; the floor's top is at y = 19 × 16 = 304; walls
// one tile thick at both ends (inner faces at x = 16 and x = 624).
std::vector<std::string> levelRows() {
    std::vector<std::string> rows(19, "#" + std::string(38, '.') + "#");
    rows.push_back(std::string(40, '#'));
    return rows;
}

struct Platformer {
    World world{WorldDef{.gravity = {0, kG}}};
    TileMapId level = createTileMap(world, {.x = 0, .y = 0, .tile = kTile, .rows = levelRows()});
    // A jump-through ledge with its top 64 above the floor, from x = 200 to 300.
    BodyId ledge = world.createBody({.type = BodyType::Static,
                                     .x = 250,
                                     .y = 304 - 64 + 4,
                                     .hw = 50,
                                     .hh = 4,
                                     .oneWay = {0, -1}});
    // A lift resting on the floor at x = 500 (top 16 above the floor).
    BodyId lift = world.createBody(
        {.type = BodyType::Kinematic, .x = 500, .y = 304 - 8, .hw = 30, .hh = 8, .friction = 1});
    // The character: 12 × 16, no friction (the game sets its walking speed).
    BodyId hero = world.createBody({.x = 60, .y = 304 - 8, .hw = 6, .hh = 8, .friction = 0});
    FixedStep clock{kDt};

    bool onFloor() const { return world.touching(hero).floor; }
    Vec2 at() const { return world.position(hero); }
    /// Runs `seconds` of frames of 1/60 s, walking at `walk` (units/s) and jumping with
    /// `jump` (units/s up) whenever on the floor and `jumping` is set.
    void play(float seconds, float walk, float jump = 0.0f) {
        for (int frame = 0; frame < int(std::lround(seconds * 60)); ++frame) {
            Vec2 v = world.velocity(hero);
            v.x = walk;
            if (jump > 0 && onFloor())
                v.y = -jump;
            world.setVelocity(hero, v);
            clock.update(world, kDt);
        }
    }
};

// The launch speed that peaks `height` above the start: sqrt(2 g h).
float jumpSpeed(float height) {
    return std::sqrt(2 * kG * height);
}

TEST(Platformer, WalksJumpsThroughRidesAndSlides) {
    Platformer game;
    game.play(0.5f, 0); // settle on the floor
    ASSERT_TRUE(game.onFloor());
    ASSERT_NEAR(game.at().y, 296.0f, 0.05f);

    // Walk right along the tile floor at 120 units/s for a second: 120 units, no snag.
    game.play(1.0f, 120);
    EXPECT_NEAR(game.at().x, 180.0f, 0.5f);
    EXPECT_NEAR(game.at().y, 296.0f, 0.05f);

    // Walk under the ledge and jump 100 high: through it from below, onto its top (y 240).
    game.play(0.5f, 120); // x = 240
    game.play(0.1f, 0, jumpSpeed(100));
    game.play(1.5f, 0);
    EXPECT_NEAR(game.at().y, 240.0f - 8.0f, 0.05f);
    EXPECT_TRUE(game.onFloor());
    EXPECT_EQ(game.world.touching(game.hero).floor, true);

    // A ray straight down from the hero's feet meets the ledge first, the floor below it.
    const std::vector<RayHit> below =
        rayCastAll(game.world, game.at(), game.at() + Vec2{0, 200}, {.ignore = game.hero});
    ASSERT_GE(below.size(), 2u);
    EXPECT_EQ(below[0].body, game.ledge);
    EXPECT_EQ(tileMapOf(game.world, below[1].body), game.level);

    // Down + jump: through the ledge, back on the floor.
    game.world.dropThrough(game.hero, 0.3f);
    game.play(1.0f, 0);
    EXPECT_NEAR(game.at().y, 296.0f, 0.05f);

    // Walk to x = 440 and hop onto the lift (x 470 to 530, top 16 above the floor),
    // walking on: launched at sqrt(2 g 40) = 253, it comes down to the lift's height
    // after (253 + sqrt(253² - 2 × 800 × 16)) / 800 = 0.56 s, at x = 440 + 120 × 0.56 = 507.
    game.play(100.0f / 60, 120);
    ASSERT_NEAR(game.at().x, 440.0f, 0.5f);
    game.play(1.0f / 60, 120, jumpSpeed(40));
    game.play(35.0f / 60, 120);
    game.play(0.3f, 0);
    ASSERT_NEAR(game.at().y, 288.0f - 8.0f, 0.05f);
    ASSERT_GT(game.at().x, 470.0f);
    ASSERT_LT(game.at().x, 530.0f);

    // The lift goes up 120 units in two seconds and stops: the hero goes with it.
    const float x = game.at().x;
    game.world.setVelocity(game.lift, {0, -60});
    game.play(2.0f, 0);
    game.world.setVelocity(game.lift, {0, 0});
    game.play(0.5f, 0);
    EXPECT_NEAR(game.at().y, 288.0f - 120.0f - 8.0f, 0.1f);
    EXPECT_NEAR(game.at().x, x, 0.01f);
    EXPECT_TRUE(game.onFloor());

    // Off the lift to the right and against the right wall, falling along its tiles: the
    // hero pressed against it falls freely, as far as the floor.
    game.play(0.5f, 300);
    EXPECT_TRUE(game.world.touching(game.hero).wallRight);
    game.play(1.5f, 300);
    EXPECT_NEAR(game.at().x, 624.0f - 6.0f, 0.05f);
    EXPECT_NEAR(game.at().y, 296.0f, 0.05f);

    // Something to stand on ahead? A box query one tile ahead of the hero's feet.
    EXPECT_TRUE(
        queryBox(game.world, game.at() + Vec2{-20, 8}, {2, 2}, {.ignore = game.hero}).size() >= 1);
}

} // namespace
} // namespace jostle
