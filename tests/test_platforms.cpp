// Moving platforms (kinematic bodies) and their riders, in the physical model: carried
// exactly through starts, stops and reversals, never thrown off one that starts down,
// leaving with the platform's velocity.
#include "jostle/world.hpp"

#include <gtest/gtest.h>

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

} // namespace
} // namespace jostle
