// Sleeping: bodies at rest fall asleep together and wake when something concerns them.
#include "jostle/world.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace jostle {
namespace {

constexpr float kDt = 1.0f / 60.0f;

struct Level {
    World world{WorldDef{.gravity = {0, 800}}};
    BodyId floor =
        world.createBody({.type = BodyType::Static, .x = 0, .y = 50, .hw = 1000, .hh = 50});

    void run(float seconds) {
        for (int i = 0; i < int(seconds * 60); ++i)
            world.step(kDt);
    }
};

TEST(Sleeping, ABoxAtRestFallsAsleepAndStaysPut) {
    Level level;
    BodyId box = level.world.createBody({.x = 0, .y = -5, .hw = 5, .hh = 5});
    level.run(0.25f);
    EXPECT_TRUE(level.world.isAwake(box)); // not yet: half a second of rest is needed
    level.run(1);
    EXPECT_FALSE(level.world.isAwake(box));
    const Vec2 p = level.world.position(box);
    level.run(10);
    EXPECT_EQ(level.world.position(box), p);
    EXPECT_EQ(level.world.velocity(box), (Vec2{0, 0}));
}

TEST(Sleeping, AStackFallsAsleepTogether) {
    Level level;
    std::vector<BodyId> stack;
    for (int i = 0; i < 5; ++i)
        stack.push_back(
            level.world.createBody({.x = 0, .y = -5.0f - 10.0f * float(i), .hw = 5, .hh = 5}));
    BodyId falling = level.world.createBody({.x = 0, .y = -300, .hw = 5, .hh = 5});
    // The stack is at rest at once, but the falling box lands on it only after 0.8 s.
    for (int i = 0; i < 60 * 3; ++i) {
        level.world.step(kDt);
        const bool bottom = level.world.isAwake(stack.front());
        for (BodyId id : stack)
            ASSERT_EQ(level.world.isAwake(id), bottom) << "step " << i;
    }
    EXPECT_FALSE(level.world.isAwake(stack.front()));
    EXPECT_FALSE(level.world.isAwake(falling));
    EXPECT_NEAR(level.world.position(falling).y, -55.0f, 0.3f);
}

// Found by fuzz_api (tests/fuzz/corpus/api/asleep-beyond-slop-1): two small boxes
// dropped one above the other. The island fell asleep while position correction was
// still pushing them apart, by less than the sleep speed, and they slept 2.5% deeper than
// the slop. An island sleeps only once every contact of it is within the slop (to float
// noise, 1e-4 of the smaller half extent), and then stays so.
TEST(Sleeping, AnIslandFallsAsleepOnlyWithinTheSlop) {
    World world(WorldDef{.gravity = {0, -1200}});
    world.createBody({.type = BodyType::Static, .x = 0, .y = -10, .hw = 200, .hh = 10});
    BodyId lower = world.createBody({.x = 0, .y = 40.5f, .hw = 0.5f, .hh = 0.5f, .friction = 0});
    BodyId upper = world.createBody({.x = 0, .y = 42.5f, .hw = 0.5f, .hh = 0.5f, .friction = 0});
    // The slop, 0.01 of the half extent 0.5, with the noise.
    const float slop = (0.01f + 1e-4f) * 0.5f;
    bool slept = false;
    for (int i = 0; i < 8 * 30; ++i) {
        world.step(1.0f / 30.0f);
        if (world.isAwake(lower))
            continue;
        slept = true;
        // The floor's top is y = 0; the boxes are 1 high.
        ASSERT_LE(0.5f - world.position(lower).y, slop) << "step " << i;
        ASSERT_LE(world.position(lower).y + 1.0f - world.position(upper).y, slop) << "step " << i;
    }
    EXPECT_TRUE(slept);
}

TEST(Sleeping, AnAwakeBodyLandingOnASleeperWakesIt) {
    Level level;
    BodyId sleeper = level.world.createBody({.x = 0, .y = -5, .hw = 5, .hh = 5});
    level.run(1);
    ASSERT_FALSE(level.world.isAwake(sleeper));
    BodyId dropped = level.world.createBody({.x = 3, .y = -100, .hw = 5, .hh = 5});
    bool woke = false;
    for (int i = 0; i < 60; ++i) {
        level.world.step(kDt);
        woke = woke || level.world.isAwake(sleeper);
    }
    EXPECT_TRUE(woke);
    // It landed on the sleeper instead of passing through it.
    EXPECT_NEAR(level.world.position(dropped).y, -15.0f, 0.2f);
}

TEST(Sleeping, ASetterWakesTheBody) {
    Level level;
    BodyId box = level.world.createBody({.x = 0, .y = -5, .hw = 5, .hh = 5});
    level.run(1);
    ASSERT_FALSE(level.world.isAwake(box));
    level.world.setVelocity(box, {60, 0});
    EXPECT_TRUE(level.world.isAwake(box));
    level.world.step(kDt);
    EXPECT_GT(level.world.position(box).x, 0.0f);
}

TEST(Sleeping, DestroyingWhatItRestsOnWakesIt) {
    Level level;
    BodyId box = level.world.createBody({.x = 0, .y = -5, .hw = 5, .hh = 5});
    level.run(1);
    ASSERT_FALSE(level.world.isAwake(box));
    level.world.destroyBody(level.floor);
    EXPECT_TRUE(level.world.isAwake(box));
    level.run(0.5f);
    EXPECT_GT(level.world.position(box).y, 50.0f); // fell
}

TEST(Sleeping, APlatformThatStartsMovingWakesItsRider) {
    World world{WorldDef{.gravity = {0, 800}}};
    BodyId lift =
        world.createBody({.type = BodyType::Kinematic, .x = 0, .y = 5, .hw = 50, .hh = 5});
    BodyId rider = world.createBody({.x = 0, .y = -5, .hw = 5, .hh = 5});
    for (int i = 0; i < 60; ++i)
        world.step(kDt);
    ASSERT_FALSE(world.isAwake(rider));
    world.setVelocity(lift, {0, -60});
    EXPECT_TRUE(world.isAwake(rider));
    for (int i = 0; i < 60; ++i)
        world.step(kDt);
    // Carried up by 60 with the lift, still on it, and never asleep meanwhile.
    EXPECT_NEAR(world.position(rider).y, -65.0f, 0.1f);
    EXPECT_TRUE(world.isAwake(rider));
}

TEST(Sleeping, ABodyMovedByTheUserWakesWhatRestedOnIt) {
    Level level;
    BodyId shelf =
        level.world.createBody({.type = BodyType::Static, .x = 0, .y = -200, .hw = 20, .hh = 5});
    BodyId box = level.world.createBody({.x = 0, .y = -210, .hw = 5, .hh = 5});
    level.run(1);
    ASSERT_FALSE(level.world.isAwake(box));
    level.world.setPosition(shelf, {500, -200});
    EXPECT_TRUE(level.world.isAwake(box));
    level.run(1);
    EXPECT_NEAR(level.world.position(box).y, -5.0f, 0.1f); // fell to the floor
}

TEST(Sleeping, WakeWakesTheBodyForAWhile) {
    Level level;
    BodyId box = level.world.createBody({.x = 0, .y = -5, .hw = 5, .hh = 5});
    level.run(2);
    ASSERT_FALSE(level.world.isAwake(box));
    level.world.wake(box);
    EXPECT_TRUE(level.world.isAwake(box));
    // Still at rest, it falls asleep again only after the half second of rest sleep needs.
    level.run(0.25f);
    EXPECT_TRUE(level.world.isAwake(box));
}

TEST(Sleeping, ASleepingBodyStillReadsAsGrounded) {
    // separation() is how a game tells that a body stands on something; sleeping on the
    // floor does not make it airborne.
    Level level;
    BodyId box = level.world.createBody({.x = 0, .y = -5, .hw = 5, .hh = 5});
    level.run(3);
    ASSERT_FALSE(level.world.isAwake(box));
    EXPECT_LT(level.world.separation(box).y, 0.0f); // pushed up, out of the floor
}

TEST(Sleeping, CanBeTurnedOff) {
    World world{WorldDef{.gravity = {0, 800}, .sleeping = false}};
    world.createBody({.type = BodyType::Static, .x = 0, .y = 50, .hw = 1000, .hh = 50});
    BodyId box = world.createBody({.x = 0, .y = -5, .hw = 5, .hh = 5});
    for (int i = 0; i < 600; ++i)
        world.step(kDt);
    EXPECT_TRUE(world.isAwake(box));

    World sleepy{WorldDef{.gravity = {0, 800}}};
    sleepy.createBody({.type = BodyType::Static, .x = 0, .y = 50, .hw = 1000, .hh = 50});
    BodyId other = sleepy.createBody({.x = 0, .y = -5, .hw = 5, .hh = 5});
    for (int i = 0; i < 120; ++i)
        sleepy.step(kDt);
    ASSERT_FALSE(sleepy.isAwake(other));
    sleepy.setSleeping(false);
    EXPECT_TRUE(sleepy.isAwake(other));
}

} // namespace
} // namespace jostle
