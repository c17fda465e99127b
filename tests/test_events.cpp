// What a step reports: contact begin and end, touching flags, crushes.
#include "jostle/world.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace jostle {
namespace {

constexpr float kDt = 1.0f / 60.0f;
constexpr float kG = 800.0f;

struct Level {
    explicit Level(Solver solver = Solver::Physical, bool sleeping = false)
        : world(WorldDef{.gravity = {0, kG}, .solver = solver, .sleeping = sleeping}) {}
    World world;
    // Top face at y = 0 (y grows downward).
    BodyId floor =
        world.createBody({.type = BodyType::Static, .x = 0, .y = 50, .hw = 1000, .hh = 50});
    std::vector<ContactEvent> begins, ends;

    void run(int steps) {
        for (int i = 0; i < steps; ++i) {
            world.step(kDt);
            begins.insert(begins.end(), world.contactBegins().begin(), world.contactBegins().end());
            ends.insert(ends.end(), world.contactEnds().begin(), world.contactEnds().end());
        }
    }
};

class DroppedBox : public ::testing::TestWithParam<Solver> {};

TEST_P(DroppedBox, BeginsTouchingOnceWithItsImpactSpeed) {
    Level level(GetParam());
    // Its bottom 100 above the floor: it lands at sqrt(2 g h).
    BodyId box = level.world.createBody({.x = 0, .y = -105, .hw = 5, .hh = 5});
    level.run(120);
    ASSERT_EQ(level.begins.size(), 1u);
    const ContactEvent& e = level.begins[0];
    EXPECT_EQ(e.a, level.floor); // created first
    EXPECT_EQ(e.b, box);
    EXPECT_EQ(e.normal, (Vec2{0, 1})); // from the box towards the floor
    // The speed is read at the start of the step it lands in: within one step's gravity
    // (g dt = 13.3) of the true impact speed.
    EXPECT_NEAR(e.approachSpeed, std::sqrt(2 * kG * 100), kG * kDt + 0.5f);
    EXPECT_TRUE(level.ends.empty()); // resting: still touching
    EXPECT_TRUE(level.world.touching(box).floor);
}

TEST_P(DroppedBox, EndsTouchingWhenItJumps) {
    Level level(GetParam());
    BodyId box = level.world.createBody({.x = 0, .y = -5, .hw = 5, .hh = 5});
    level.run(30);
    ASSERT_EQ(level.begins.size(), 1u);
    level.world.setVelocity(box, {0, -400});
    level.run(10);
    ASSERT_EQ(level.ends.size(), 1u);
    EXPECT_EQ(level.ends[0].a, level.floor);
    EXPECT_EQ(level.ends[0].b, box);
    EXPECT_FALSE(level.world.touching(box).floor);
}

INSTANTIATE_TEST_SUITE_P(Models, DroppedBox, ::testing::Values(Solver::Classic, Solver::Physical),
                         [](const ::testing::TestParamInfo<Solver>& model) {
                             return model.param == Solver::Classic ? "Classic" : "Physical";
                         });

TEST(Events, DestroyingABodyEndsItsContacts) {
    Level level;
    BodyId box = level.world.createBody({.x = 0, .y = -5, .hw = 5, .hh = 5});
    level.run(10);
    level.world.destroyBody(box);
    level.run(1);
    ASSERT_EQ(level.ends.size(), 1u);
    EXPECT_EQ(level.ends[0].b, box); // the handle it had, now stale
    EXPECT_FALSE(level.world.isValid(level.ends[0].b));
}

TEST(Events, FallingAsleepEndsNothing) {
    Level level(Solver::Physical, true);
    BodyId box = level.world.createBody({.x = 0, .y = -5, .hw = 5, .hh = 5});
    level.run(300);
    ASSERT_FALSE(level.world.isAwake(box));
    EXPECT_EQ(level.begins.size(), 1u);
    EXPECT_TRUE(level.ends.empty());
    EXPECT_TRUE(level.world.touching(box).floor);
}

TEST(Touching, WallsAndCeilingRelativeToGravity) {
    Level level;
    // Walls at x = ±20 (inner faces), a ceiling with its bottom face at y = -40.
    level.world.createBody({.type = BodyType::Static, .x = 30, .y = -50, .hw = 10, .hh = 50});
    level.world.createBody({.type = BodyType::Static, .x = -30, .y = -50, .hw = 10, .hh = 50});
    level.world.createBody({.type = BodyType::Static, .x = 0, .y = -50, .hw = 20, .hh = 10});
    BodyId right = level.world.createBody({.x = 10, .y = -5, .hw = 5, .hh = 5, .vx = 200});
    BodyId left = level.world.createBody({.x = -10, .y = -5, .hw = 5, .hh = 5, .vx = -200});
    BodyId up = level.world.createBody({.x = 0, .y = -20, .hw = 4, .hh = 4, .gravityScale = -1});
    level.run(30);
    const Touching r = level.world.touching(right);
    EXPECT_TRUE(r.floor && r.wallRight && !r.wallLeft && !r.ceiling);
    const Touching l = level.world.touching(left);
    EXPECT_TRUE(l.floor && l.wallLeft && !l.wallRight && !l.ceiling);
    const Touching u = level.world.touching(up);
    EXPECT_TRUE(u.ceiling && !u.floor);
}

TEST(Touching, FollowsGravityWhenItTurns) {
    // Gravity pulling right: the wall on the right is the floor now.
    World world(WorldDef{.gravity = {kG, 0}, .sleeping = false});
    world.createBody({.type = BodyType::Static, .x = 50, .y = 0, .hw = 40, .hh = 1000});
    BodyId box = world.createBody({.x = 0, .y = 0, .hw = 5, .hh = 5});
    for (int i = 0; i < 60; ++i)
        world.step(kDt);
    EXPECT_TRUE(world.touching(box).floor);
}

TEST(Crush, ABoxUnderADescendingBlockIsReported) {
    Level level;
    BodyId box = level.world.createBody({.x = 0, .y = -5, .hw = 5, .hh = 5});
    BodyId block = level.world.createBody(
        {.type = BodyType::Kinematic, .x = 0, .y = -40, .hw = 30, .hh = 10, .vy = 60});
    bool crushed = false;
    for (int i = 0; i < 120 && !crushed; ++i) {
        level.world.step(kDt);
        for (const CrushEvent& e : level.world.crushes()) {
            EXPECT_EQ(e.body, box);
            EXPECT_EQ(e.by, block);
            EXPECT_EQ(e.against, level.floor);
            crushed = true;
        }
    }
    EXPECT_TRUE(crushed);
}

TEST(Crush, ARiderOnALiftIsNotCrushed) {
    Level level;
    BodyId lift = level.world.createBody(
        {.type = BodyType::Kinematic, .x = 0, .y = -10, .hw = 30, .hh = 10, .vy = -60});
    level.world.createBody({.x = 0, .y = -25, .hw = 5, .hh = 5});
    for (int i = 0; i < 60; ++i) {
        level.world.step(kDt);
        EXPECT_TRUE(level.world.crushes().empty()) << "step " << i;
    }
    (void)lift;
}

} // namespace
} // namespace jostle
