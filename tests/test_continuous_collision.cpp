// Continuous collision: nothing passes through a wall, at any speed.
#include "jostle/world.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace jostle {
namespace {

constexpr float kDt = 1.0f / 60.0f;

class FastBox : public ::testing::TestWithParam<std::tuple<float, float>> {};

TEST_P(FastBox, NeverPassesAThinWall) {
    // A 4-unit box at 30,000 units/s (500 units a step) against a wall 2 units thick, at
    // several phases (where the wall falls within a step) and angles of approach.
    const auto [phase, angle] = GetParam();
    World world(WorldDef{.gravity = {0, 800}, .sleeping = false});
    const float wallX = 1000;
    // Tall enough that no angle gets round it within the test.
    world.createBody({.type = BodyType::Static, .x = wallX, .y = 0, .hw = 1, .hh = 1e6f});
    const float speed = 30000;
    BodyId box = world.createBody({.x = phase * 500.0f,
                                   .y = 0,
                                   .hw = 2,
                                   .hh = 2,
                                   .vx = speed * std::cos(angle),
                                   .vy = speed * std::sin(angle)});
    for (int i = 0; i < 120; ++i) {
        world.step(kDt);
        // Its right edge never goes beyond the wall's left face (999).
        ASSERT_LE(world.position(box).x + 2, wallX - 1 + 1e-3f) << "step " << i;
    }
}

INSTANTIATE_TEST_SUITE_P(PhasesAndAngles, FastBox,
                         ::testing::Combine(::testing::Values(0.0f, 0.13f, 0.5f, 0.77f, 0.996f),
                                            ::testing::Values(0.0f, 0.3f, -0.6f, 1.2f)));

TEST(Ccd, AFastBoxStopsAtTheWallItHits) {
    World world(WorldDef{.sleeping = false});
    world.createBody({.type = BodyType::Static, .x = 1000, .y = 0, .hw = 1, .hh = 100});
    BodyId box = world.createBody({.x = 0, .y = 0, .hw = 2, .hh = 2, .vx = 30000});
    for (int i = 0; i < 10; ++i)
        world.step(kDt);
    EXPECT_NEAR(world.position(box).x, 997.0f, 0.05f); // resting against the face at 999
    EXPECT_EQ(world.velocity(box).x, 0.0f);
}

TEST(Ccd, NeverPassesAKinematicWallComingTowardsIt) {
    World world(WorldDef{.sleeping = false});
    BodyId wall = world.createBody(
        {.type = BodyType::Kinematic, .x = 1000, .y = 0, .hw = 1, .hh = 100, .vx = -3000});
    BodyId box = world.createBody({.x = 0, .y = 0, .hw = 2, .hh = 2, .vx = 30000});
    for (int i = 0; i < 60; ++i) {
        world.step(kDt);
        ASSERT_LE(world.position(box).x, world.position(wall).x) << "step " << i;
    }
}

TEST(Ccd, ABoxStruckIntoAWallByAFastPaddleStopsAtTheWall) {
    // The box is at rest when the step begins, so no contact with the wall is foreseen;
    // the paddle's contact then gives it 30,000 units/s. Only the sweep stops it.
    World world(WorldDef{.sleeping = false});
    world.createBody({.type = BodyType::Static, .x = 200, .y = 0, .hw = 1, .hh = 100});
    BodyId paddle = world.createBody(
        {.type = BodyType::Kinematic, .x = -50, .y = 0, .hw = 10, .hh = 50, .vx = 30000});
    BodyId box = world.createBody({.x = 0, .y = 0, .hw = 2, .hh = 2});
    world.step(kDt);
    world.setVelocity(paddle, {0, 0});
    EXPECT_GT(world.position(box).x, 100.0f); // it was struck, and flew to the wall
    for (int i = 0; i < 30; ++i) {
        // Against the wall's face at 199, touching it within the contact skin (twice the
        // slop, 1% of the smaller half extent: 0.02).
        ASSERT_LE(world.position(box).x + 2, 199.0f + 0.02f + 1e-3f) << "step " << i;
        world.step(kDt);
    }
}

// A box struck by a fast paddle into a thin dynamic plate: it starts at rest, so no
// contact with the plate is foreseen, and only a sweep against dynamic bodies, which a
// bullet gets, stops it.
float boxStruckIntoAPlate(bool bullet, float& plateX) {
    World world(WorldDef{.sleeping = false});
    BodyId plate = world.createBody({.x = 200, .y = 0, .hw = 1, .hh = 100, .mass = 1000});
    BodyId paddle = world.createBody(
        {.type = BodyType::Kinematic, .x = -50, .y = 0, .hw = 10, .hh = 50, .vx = 30000});
    BodyId box = world.createBody({.x = 0, .y = 0, .hw = 2, .hh = 2, .bullet = bullet});
    world.step(kDt);
    world.setVelocity(paddle, {0, 0});
    for (int i = 0; i < 30; ++i)
        world.step(kDt);
    plateX = world.position(plate).x;
    return world.position(box).x;
}

TEST(Ccd, ABulletDoesNotPassAThinDynamicBody) {
    float plateX = 0;
    EXPECT_LT(boxStruckIntoAPlate(true, plateX), plateX);
}

TEST(Ccd, WithoutTheBulletFlagDynamicBodiesAreNotSwept) {
    // What the flag costs and buys: without it the box goes through the plate.
    float plateX = 0;
    EXPECT_GT(boxStruckIntoAPlate(false, plateX), plateX);
}

TEST(Ccd, AFastBoxThatHitsTheFloorStillDoesNotPassTheWallBeyond) {
    // Struck downwards and sideways at once: it meets the floor first, then slides, in
    // the same step, towards a thin wall. The sweep goes on after the first hit.
    World world(WorldDef{.sleeping = false});
    world.createBody({.type = BodyType::Static, .x = 0, .y = 60, .hw = 1000, .hh = 10});
    world.createBody({.type = BodyType::Static, .x = 300, .y = -25, .hw = 1, .hh = 75});
    BodyId paddle = world.createBody({.type = BodyType::Kinematic,
                                      .x = -50,
                                      .y = 0,
                                      .hw = 10,
                                      .hh = 50,
                                      .vx = 30000,
                                      .vy = 15000,
                                      .friction = 1});
    BodyId box = world.createBody({.x = 0, .y = 0, .hw = 2, .hh = 2, .friction = 1});
    for (int i = 0; i < 30; ++i) {
        world.step(kDt);
        if (i == 0)
            world.setVelocity(paddle, {0, 0});
        // The wall's face is at x = 299: the box's right edge stays before it (within
        // the contact skin, 0.02).
        ASSERT_LE(world.position(box).x + 2, 299.0f + 0.02f + 1e-3f) << "step " << i;
    }
}

TEST(Ccd, TheClassicModelTunnelsLikeTheTutorialUnlessAsked) {
    auto finalX = [](bool ccd) {
        World world(WorldDef{.solver = Solver::Classic, .classic = {.ccd = ccd}});
        world.createBody({.type = BodyType::Static, .x = 1000, .y = 0, .hw = 1, .hh = 100});
        BodyId box = world.createBody({.x = 0, .y = 0, .hw = 2, .hh = 2, .vx = 30000});
        for (int i = 0; i < 10; ++i)
            world.step(kDt);
        return world.position(box).x;
    };
    EXPECT_GT(finalX(false), 1001.0f); // straight through, as the tutorial's code does
    EXPECT_LE(finalX(true), 997.0f + 1e-3f);
}

TEST(Ccd, TheClassicSweepLetsABoxSlideAlongAFloor) {
    // Under gravity a box on a floor moves into it every step; the sweep meets the floor
    // at once, and must go on along it. Friction 0: it slides 300 units in a second.
    World world(WorldDef{.gravity = {0, 800}, .solver = Solver::Classic, .classic = {.ccd = true}});
    world.createBody({.type = BodyType::Static, .x = 0, .y = 50, .hw = 1000, .hh = 50});
    BodyId box = world.createBody({.x = -900, .y = -5, .hw = 5, .hh = 5, .vx = 300, .friction = 0});
    for (int i = 0; i < 60; ++i)
        world.step(kDt);
    // 60 steps of 5 units each, summed in floats: well within 0.01.
    EXPECT_NEAR(world.position(box).x, -600.0f, 0.01f);
    EXPECT_NEAR(world.position(box).y, -5.0f, 1e-3f);
}

TEST(Ccd, TheClassicSweepStopsAKinematicWallComingTowardsIt) {
    // A fast box and a fast kinematic wall close at 60,000 units/s: 1,000 units a step.
    World world(WorldDef{.solver = Solver::Classic, .classic = {.ccd = true}});
    BodyId wall = world.createBody(
        {.type = BodyType::Kinematic, .x = 1500, .y = 0, .hw = 1, .hh = 100, .vx = -30000});
    BodyId box = world.createBody({.x = 0, .y = 0, .hw = 2, .hh = 2, .vx = 30000});
    for (int i = 0; i < 3; ++i) {
        world.step(kDt);
        ASSERT_LT(world.position(box).x, world.position(wall).x) << "step " << i;
    }
}

} // namespace
} // namespace jostle
