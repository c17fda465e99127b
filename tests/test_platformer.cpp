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

// --- A character ----------------------------------------------------------------------------
//
// The same kind of level, played by a character (BodyDef::character) with the default
// friction, the way docs/characters.md makes one: the game sets a walk speed from its input
// every frame and jumps by setting the vertical speed; nothing else. A guard, a kinematic
// body, is moved by hand with move().

// 60 tiles wide. The floor's top is at y = 304, with a pit from x = 480 to 640 (tiles 30 to
// 39) that a ferry crosses and a lift's shaft from x = 768 to 832 (tiles 48 to 51); a wall
// 48 high at x = 192 to 208 (tile 12); a block at tiles 20 and 21 (x 320 to 352) whose top
// is 32 above the floor.
std::vector<std::string> characterLevelRows() {
    std::vector<std::string> rows(19, "#" + std::string(58, '.') + "#");
    rows.push_back(std::string(30, '#') + std::string(10, '.') + std::string(8, '#') +
                   std::string(4, '.') + std::string(8, '#'));
    for (int row = 16; row < 19; ++row)
        rows[std::size_t(row)][12] = '#';
    for (int row = 17; row < 19; ++row)
        rows[std::size_t(row)][20] = rows[std::size_t(row)][21] = '#';
    return rows;
}

/// How high a jump at `speed` rises in steps of kDt (the integrator's, not v² / 2g: each
/// step moves by the speed after that step's gravity).
float discreteJumpHeight(float speed) {
    float height = 0, v = speed;
    while ((v -= kG * kDt) > 0)
        height += v * kDt;
    return height;
}

struct CharacterGame {
    World world{WorldDef{.gravity = {0, kG}}};
    TileMapId level =
        createTileMap(world, {.x = 0, .y = 0, .tile = kTile, .rows = characterLevelRows()});
    BodyId hero = world.createBody({.x = 40, .y = 296, .hw = 6, .hh = 8, .character = true});
    BodyId crate = world.createBody({.x = 120, .y = 296, .hw = 8, .hh = 8, .friction = 0.3f});
    // On the block's top.
    BodyId coin = world.createBody(
        {.type = BodyType::Static, .x = 330, .y = 266, .hw = 4, .hh = 4, .sensor = true});
    // Spans the pit's first 60 units, its top at the floor's height.
    BodyId ferry =
        world.createBody({.type = BodyType::Kinematic, .x = 510, .y = 312, .hw = 30, .hh = 8});
    // Beyond the pit: a lift in its shaft, its top at the floor's height.
    BodyId lift =
        world.createBody({.type = BodyType::Kinematic, .x = 800, .y = 312, .hw = 24, .hh = 8});
    FixedStep clock{kDt};
    int coins = 0;

    Vec2 at() const { return world.position(hero); }
    bool standsOn(BodyId body) const {
        const std::optional<Ground> ground = world.ground(hero);
        return ground && ground->body == body;
    }
    /// A frame of 1/60 s, walking at `walk`; a jump at `jump` units/s if on the ground.
    void frame(float walk, float jump = 0.0f) {
        world.setWalkSpeed(hero, walk);
        if (jump > 0 && world.ground(hero))
            world.setVelocity(hero, {world.velocity(hero).x, -jump});
        clock.update(world, kDt);
        for (const SensorEvent& e : world.sensorBegins())
            coins += e.sensor == coin && e.visitor == hero;
    }
    void play(int frames, float walk) {
        for (int i = 0; i < frames; ++i)
            frame(walk);
    }
};

TEST(Platformer, ACharacterPlaysTheLevelWithNoWorkaround) {
    CharacterGame game;
    game.play(30, 0);
    ASSERT_TRUE(game.world.ground(game.hero));

    // Walks at exactly the commanded speed on the floor (friction takes nothing), then
    // pushes the crate (x 112 to 128) ahead of it.
    game.play(10, 150);
    EXPECT_EQ(game.world.velocity(game.hero).x, 150.0f);
    game.play(60, 150);
    EXPECT_GT(game.world.position(game.crate).x, 150.0f);
    EXPECT_LT(game.at().x, game.world.position(game.crate).x);
    EXPECT_TRUE(game.world.isTouching(game.hero, game.crate));

    // Against the wall (x = 192), a jump while pressing into it rises as in open air,
    // clears the wall's top (48 up) and lands beyond it.
    game.world.setPosition(game.crate, {90, 296}); // out of the way
    game.world.setPosition(game.hero, {170, 296});
    game.play(20, 150);
    ASSERT_TRUE(game.world.touching(game.hero).wallRight);
    const float floorY = game.at().y, jump = std::sqrt(2 * kG * 99);
    float highest = floorY;
    for (int i = 0; i < 40; ++i) {
        game.frame(150, i == 0 ? jump : 0.0f);
        highest = std::min(highest, game.at().y);
    }
    EXPECT_NEAR(floorY - highest, discreteJumpHeight(jump), 0.01f * discreteJumpHeight(jump));
    game.play(30, 150);
    EXPECT_GT(game.at().x, 208.0f);
    EXPECT_NEAR(game.at().y, floorY, 0.05f);

    // Up onto the block from x = 260, jumping 40 high: its path clears the corner at
    // (320, 272), so it walks at 150 all the way, lands on the top and takes the coin.
    game.world.setPosition(game.hero, {260, 296});
    game.play(5, 0);
    game.frame(150, std::sqrt(2 * kG * 40));
    for (int i = 0; i < 40 && !game.world.ground(game.hero); ++i) {
        game.frame(150);
        EXPECT_EQ(game.world.velocity(game.hero).x, 150.0f) << "frame " << i;
    }
    game.play(3, 0);
    EXPECT_NEAR(game.at().y, 272.0f - 8.0f, 0.05f);
    EXPECT_EQ(game.coins, 1);

    // Down to the pit's edge and onto the ferry, which crosses the pit (100 to the right in
    // 2 s) and stops while the hero stands on it: it rides exactly, then walks off.
    game.world.setPosition(game.hero, {510, 296});
    game.play(10, 0);
    ASSERT_TRUE(game.standsOn(game.ferry));
    const float onFerry = game.at().x - game.world.position(game.ferry).x;
    game.world.setVelocity(game.ferry, {50, 0});
    game.play(120, 0);
    EXPECT_TRUE(game.standsOn(game.ferry));
    EXPECT_EQ(game.world.ground(game.hero)->velocity, (Vec2{50, 0}));
    game.world.setVelocity(game.ferry, {0, 0});
    game.play(10, 0);
    EXPECT_NEAR(game.at().x - game.world.position(game.ferry).x, onFerry, 1e-3f);
    game.play(40, 150);
    EXPECT_GT(game.at().x, 640.0f);
    EXPECT_FALSE(game.standsOn(game.ferry));

    // The lift: up 96 in 2 s, then down again, the hero standing on it, walking at 0.
    game.world.setPosition(game.hero, {800, 296});
    game.play(10, 0);
    ASSERT_TRUE(game.standsOn(game.lift));
    for (float vy : {-48.0f, 48.0f}) {
        game.world.setVelocity(game.lift, {0, vy});
        game.play(120, 0);
        EXPECT_NEAR(game.at().y, game.world.position(game.lift).y - 16, 0.2f);
        EXPECT_NEAR(game.at().x, 800.0f, 1e-3f);
        EXPECT_TRUE(game.standsOn(game.lift));
    }

    // Drawn between the last two steps: frames of exactly a step leave alpha at 0, which
    // draws the hero where it was before the last one.
    const Vec2 before = game.at();
    game.play(1, 0);
    EXPECT_EQ(game.clock.alpha(), 0.0f);
    EXPECT_EQ(game.clock.drawPosition(game.world, game.hero), before);
}

TEST(Platformer, AGuardMovedByHandSlidesAlongTheLevel) {
    // A kinematic guard moved with move(): walking right along the floor it stops at the
    // wall's face (x = 192), sliding down onto the floor while falling.
    CharacterGame game;
    const BodyId guard =
        game.world.createBody({.type = BodyType::Kinematic, .x = 150, .y = 290, .hw = 6, .hh = 8});
    const MoveOutcome out = move(game.world, guard, {100, 40});
    EXPECT_EQ(out.centre, (Vec2{186, 296}));
    ASSERT_EQ(out.collisions.size(), 2u); // the floor, then the wall
    EXPECT_EQ(out.collisions[0].normal, (Vec2{0, -1}));
    EXPECT_EQ(out.collisions[1].normal, (Vec2{-1, 0}));
    EXPECT_EQ(game.world.position(guard), out.centre);
}

} // namespace
} // namespace jostle
