// One-way platforms: blocking from one side only, landing only from wholly above, and
// dropping through on purpose (physical model).
#include "jostle/world.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace jostle {
namespace {

constexpr float kDt = 1.0f / 60.0f;
constexpr float kG = 800.0f;

// A floor with its top at y = 0 and a jump-through platform whose top is at y = -100
// (10 thick), blocking from above: oneWay = {0, -1} in a y-down world.
struct Level {
    World world{WorldDef{.gravity = {0, kG}, .sleeping = false}};
    BodyId floor =
        world.createBody({.type = BodyType::Static, .x = 0, .y = 50, .hw = 1000, .hh = 50});
    BodyId platform = world.createBody(
        {.type = BodyType::Static, .x = 0, .y = -95, .hw = 50, .hh = 5, .oneWay = {0, -1}});

    void run(float seconds) {
        for (int i = 0; i < int(std::lround(seconds * 60)); ++i)
            world.step(kDt);
    }
};

// The launch speed that peaks `height` above the start: sqrt(2 g h).
float jumpSpeed(float height) {
    return std::sqrt(2 * kG * height);
}

TEST(OneWay, AJumpFromBelowPassesThroughAndLandsOnTop) {
    Level level;
    // Bottom at 0; the platform's top is 100 up, the jump peaks 150 up.
    BodyId box = level.world.createBody({.x = 0, .y = -5, .hw = 5, .hh = 5, .vy = -jumpSpeed(150)});
    level.run(2);
    EXPECT_NEAR(level.world.position(box).y, -105.0f, 0.1f); // standing on the platform
}

TEST(OneWay, AJumpThatPeaksInsideThePlatformFallsBackDown) {
    Level level;
    // Peaks 95 up: its top is inside the platform at the peak, its bottom well below
    // the top face. It must not snap up onto the platform.
    BodyId box = level.world.createBody({.x = 0, .y = -5, .hw = 5, .hh = 5, .vy = -jumpSpeed(95)});
    level.run(2);
    EXPECT_NEAR(level.world.position(box).y, -5.0f, 0.1f); // back on the floor
}

TEST(OneWay, AJumpThatPeaksWithItsBottomJustBelowTheTopFallsBackDown) {
    Level level;
    // Peaks with its bottom 1 below the platform's top: the worst case for snapping.
    BodyId box = level.world.createBody({.x = 0, .y = -5, .hw = 5, .hh = 5, .vy = -jumpSpeed(99)});
    level.run(2);
    EXPECT_NEAR(level.world.position(box).y, -5.0f, 0.1f);
}

TEST(OneWay, SidewaysItIsNoObstacle) {
    Level level;
    // At the platform's height, moving right into its side, with no gravity.
    BodyId box = level.world.createBody(
        {.x = -80, .y = -95, .hw = 5, .hh = 5, .vx = 300, .gravityScale = 0});
    level.run(1);
    EXPECT_GT(level.world.position(box).x, 100.0f);
}

TEST(OneWay, ABoxDroppedOnItStays) {
    Level level;
    BodyId box = level.world.createBody({.x = 0, .y = -300, .hw = 5, .hh = 5});
    level.run(3);
    EXPECT_NEAR(level.world.position(box).y, -105.0f, 0.1f);
}

TEST(OneWay, AFastFallIsStoppedByTheSweep) {
    Level level;
    // 30,000 units/s down: 500 a step, far more than the platform is thick.
    BodyId box = level.world.createBody({.x = 0, .y = -700, .hw = 5, .hh = 5, .vy = 30000});
    level.run(1);
    EXPECT_NEAR(level.world.position(box).y, -105.0f, 0.1f);
}

TEST(OneWay, AFastJumpFromBelowIsNotStoppedByTheSweep) {
    Level level;
    BodyId box = level.world.createBody({.x = 0, .y = -5, .hw = 5, .hh = 5, .vy = -30000});
    level.world.step(kDt);
    EXPECT_LT(level.world.position(box).y, -200.0f);
}

TEST(OneWay, DropThroughLetsABodyFallThroughForAWhile) {
    Level level;
    BodyId box = level.world.createBody({.x = 0, .y = -105, .hw = 5, .hh = 5});
    level.run(0.5f);
    ASSERT_NEAR(level.world.position(box).y, -105.0f, 0.1f);
    level.world.dropThrough(box, 0.25f);
    level.run(2);
    EXPECT_NEAR(level.world.position(box).y, -5.0f, 0.1f); // on the floor below
    // Over: the platform blocks it again on the next jump.
    level.world.setVelocity(box, {0, -jumpSpeed(150)});
    level.run(2);
    EXPECT_NEAR(level.world.position(box).y, -105.0f, 0.1f);
}

TEST(OneWay, OnlyAxisNormalsAreAccepted) {
    World world;
    EXPECT_THROW(world.createBody({.hw = 1, .hh = 1, .oneWay = {0.6f, 0.8f}}), Error);
    BodyId body = world.createBody({.hw = 1, .hh = 1});
    EXPECT_THROW(world.setOneWay(body, {0, 2}), Error);
    world.setOneWay(body, {-1, 0});
    EXPECT_EQ(world.oneWay(body), (Vec2{-1, 0}));
    EXPECT_THROW(world.dropThrough(body, -1), Error);
}

// Only a dynamic body falls onto platforms and so drops through them: asking it of a
// static or kinematic body is a mistake, refused like any bad argument.
TEST(OneWay, DropThroughRefusesStaticAndKinematicBodies) {
    World world;
    const BodyId platform =
        world.createBody({.type = BodyType::Static, .hw = 50, .hh = 5, .oneWay = {0.0f, -1.0f}});
    const BodyId lift = world.createBody({.type = BodyType::Kinematic, .hw = 20, .hh = 5});
    for (const BodyId body : {platform, lift}) {
        try {
            world.dropThrough(body, 0.25f);
            ADD_FAILURE() << "dropThrough on a " << toString(world.type(body))
                          << " body was accepted";
        } catch (const Error& e) {
            EXPECT_STREQ(e.what(),
                         "dropThrough: only a dynamic body drops through one-way platforms");
        }
    }
    // A body made dynamic may.
    world.setType(lift, BodyType::Dynamic);
    EXPECT_NO_THROW(world.dropThrough(lift, 0.25f));
}

} // namespace
} // namespace jostle
