// Moving platforms (kinematic bodies) and their riders, in the physical model: carried
// exactly through starts, stops and reversals, never thrown off one that starts down,
// leaving with the platform's velocity.
#include "jostle/world.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace jostle {
namespace {

constexpr float kDt = 1.0f / 60.0f;
constexpr float kG = 800.0f;

struct Ride {
    World world{WorldDef{.gravity = {0, kG}, .sleeping = false}};
    // Top face at y = 0, 100 wide; the rider stands on it, its bottom at y = 0.
    BodyId platform = world.createBody(
        {.type = BodyType::Kinematic, .x = 0, .y = 5, .hw = 50, .hh = 5, .friction = 0.5f});
    BodyId rider = world.createBody({.x = 0, .y = -5, .hw = 5, .hh = 5, .friction = 0.5f});

    Vec2 offset() const { return world.position(rider) - world.position(platform); }
    void run(int steps) {
        for (int i = 0; i < steps; ++i)
            world.step(kDt);
    }
};

TEST(Platforms, ARiderStaysPutOnAPlatformThatReverses) {
    Ride ride;
    ride.run(30); // settled
    const Vec2 start = ride.offset();
    for (int leg = 0; leg < 6; ++leg) {
        // Back and forth at 200 units/s, reversing at once every half second.
        ride.world.setVelocity(ride.platform, {leg % 2 == 0 ? 200.0f : -200.0f, 0});
        for (int i = 0; i < 30; ++i) {
            ride.world.step(kDt);
            // Carried exactly: the offset moves only by float rounding of the positions
            // (a few ulps of 200 units).
            ASSERT_NEAR(ride.offset().x, start.x, 1e-3f) << "leg " << leg << " step " << i;
            ASSERT_NEAR(ride.offset().y, start.y, 0.05f) << "leg " << leg << " step " << i;
        }
    }
}

TEST(Platforms, ARiderIsNotThrownOffAPlatformThatStartsDown) {
    Ride ride;
    ride.run(30);
    const Vec2 start = ride.offset();
    // Down at 300 units/s at once, faster than gravity could follow in a step.
    ride.world.setVelocity(ride.platform, {0, 300});
    for (int i = 0; i < 60; ++i) {
        ride.world.step(kDt);
        ASSERT_TRUE(ride.world.touching(ride.rider).floor) << "step " << i;
        ASSERT_NEAR(ride.offset().y, start.y, 0.05f) << "step " << i;
    }
}

TEST(Platforms, ARiderOfALiftThatStopsDoesNotFlyOn) {
    Ride ride;
    ride.run(30);
    ride.world.setVelocity(ride.platform, {0, -300}); // up
    ride.run(30);
    ride.world.setVelocity(ride.platform, {0, 0}); // stops at once
    ride.run(1);
    // A real rider would fly on at 300 units/s; a game's lift stops with its rider.
    EXPECT_NEAR(ride.world.velocity(ride.rider).y, 0.0f, kG * kDt + 1e-3f);
    EXPECT_TRUE(ride.world.touching(ride.rider).floor);
}

TEST(Platforms, ARiderLeavesWithThePlatformsVelocity) {
    Ride ride;
    ride.run(30);
    ride.world.setVelocity(ride.platform, {150, 0});
    ride.run(10);
    // Jumps off: keeps the 150 units/s it had with the platform.
    ride.world.setVelocity(ride.rider, {ride.world.velocity(ride.rider).x, -400});
    ride.run(5);
    EXPECT_FALSE(ride.world.touching(ride.rider).floor);
    EXPECT_NEAR(ride.world.velocity(ride.rider).x, 150.0f, 1e-3f);
}

TEST(Platforms, APlatformPushesWhatIsInItsWay) {
    Ride ride;
    // A box on the ground to the right of the platform's path, at the platform's height.
    ride.world.createBody({.type = BodyType::Static, .x = 0, .y = 60, .hw = 1000, .hh = 50});
    BodyId box = ride.world.createBody({.x = 80, .y = 5, .hw = 5, .hh = 5, .friction = 0});
    ride.world.setVelocity(ride.platform, {100, 0});
    ride.run(60);
    // The platform's right face is at 50 + 100 = 150: the box is ahead of it.
    EXPECT_GE(ride.world.position(box).x - 5, 150.0f - 0.05f);
}

// --- Conveyor belts (issue 29) --------------------------------------------------------------
//
// A static belt whose surface moves at 100 to the right (BodyDef::surfaceVelocity). A crate
// dropped on it at rest is carried by friction: with μ = 0.5 (the pair's) and g = 800 it
// speeds up at μ g = 400 until it moves with the belt, after 100 / 400 = 0.25 s.

class OnABelt : public ::testing::TestWithParam<Solver> {};

TEST(Conveyors, ACrateComesUpToTheBeltsSpeedAtMuG) {
    World world(WorldDef{.gravity = {0, 800}, .sleeping = false});
    world.createBody({.type = BodyType::Static,
                      .x = 0,
                      .y = 50,
                      .hw = 5000,
                      .hh = 50,
                      .friction = 0.5f,
                      .surfaceVelocity = {100, 0}});
    const BodyId crate = world.createBody({.x = 0, .y = -8, .hw = 8, .hh = 8, .friction = 0.5f});
    for (int i = 1; i <= 30; ++i) {
        world.step(kDt);
        const float expected = std::min(100.0f, 400.0f * kDt * float(i));
        ASSERT_NEAR(world.velocity(crate).x, expected, 0.5f) << "step " << i;
        ASSERT_NEAR(world.velocity(crate).y, 0.0f, 1e-3f);
    }
    // Resting on the belt, moving with its surface; the belt itself has not moved.
    EXPECT_TRUE(world.ground(crate));
    EXPECT_EQ(world.ground(crate)->velocity, (Vec2{100, 0}));
}

TEST(Conveyors, ACharacterWalksRelativeToTheBelt) {
    World world(WorldDef{.gravity = {0, 800}, .sleeping = false});
    const BodyId belt = world.createBody({.type = BodyType::Static,
                                          .x = 0,
                                          .y = 50,
                                          .hw = 5000,
                                          .hh = 50,
                                          .surfaceVelocity = {100, 0}});
    const BodyId hero = world.createBody({.x = 0, .y = -8, .hw = 6, .hh = 8, .character = true});
    for (int i = 0; i < 10; ++i)
        world.step(kDt);
    for (float walk : {0.0f, 50.0f, -100.0f, -250.0f}) {
        world.setWalkSpeed(hero, walk);
        for (int i = 0; i < 5; ++i) {
            world.step(kDt);
            EXPECT_NEAR(world.velocity(hero).x, 100.0f + walk, 1e-3f) << "walking at " << walk;
        }
    }
    // Turned off, the belt carries nothing: standing, the character stands.
    world.setSurfaceVelocity(belt, {});
    world.setWalkSpeed(hero, 0);
    world.step(kDt);
    EXPECT_EQ(world.velocity(hero).x, 0.0f);
}

TEST(Conveyors, OnlyStaticAndKinematicBodiesAreConveyors) {
    EXPECT_EQ(checkBodyDef({.hw = 1, .hh = 1, .surfaceVelocity = {1, 0}})->field,
              "surfaceVelocity");
    EXPECT_FALSE(
        checkBodyDef({.type = BodyType::Kinematic, .hw = 1, .hh = 1, .surfaceVelocity = {1, 0}}));
    World world;
    const BodyId crate = world.createBody({.hw = 1, .hh = 1});
    EXPECT_THROW(world.setSurfaceVelocity(crate, {1, 0}), Error);
    EXPECT_THROW(world.setSurfaceVelocity(crate, {NAN, 0}), Error);
    const BodyId belt =
        world.createBody({.type = BodyType::Static, .hw = 1, .hh = 1, .surfaceVelocity = {1, 0}});
    EXPECT_THROW(world.setType(belt, BodyType::Dynamic), Error);
    EXPECT_EQ(world.bodyDef(belt).surfaceVelocity, (Vec2{1, 0}));
}

TEST_P(OnABelt, ACrateEndsMovingWithTheBeltInEitherModel) {
    World world(WorldDef{.gravity = {0, 800}, .solver = GetParam(), .sleeping = false});
    world.createBody({.type = BodyType::Static,
                      .x = 0,
                      .y = 50,
                      .hw = 5000,
                      .hh = 50,
                      .surfaceVelocity = {-60, 0}});
    const BodyId crate = world.createBody({.x = 0, .y = -8, .hw = 8, .hh = 8});
    for (int i = 0; i < 120; ++i)
        world.step(kDt);
    EXPECT_NEAR(world.velocity(crate).x, -60.0f, 0.01f);
}

INSTANTIATE_TEST_SUITE_P(Models, OnABelt, ::testing::Values(Solver::Classic, Solver::Physical));

} // namespace
} // namespace jostle
