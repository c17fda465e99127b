// Collision filtering (category and mask) and sensors, in both models.
#include "jostle/world.hpp"

#include <gtest/gtest.h>

namespace jostle {
namespace {

constexpr float kDt = 1.0f / 60.0f;

class BothModels : public ::testing::TestWithParam<Solver> {
protected:
    World world{WorldDef{.gravity = {0, 800}, .solver = GetParam(), .sleeping = false}};
    BodyId floor =
        world.createBody({.type = BodyType::Static, .x = 0, .y = 50, .hw = 1000, .hh = 50});

    void run(int steps) {
        for (int i = 0; i < steps; ++i)
            world.step(kDt);
    }
};

constexpr std::uint32_t kPlayers = 2, kGhosts = 4;

TEST_P(BothModels, AMaskThatLeavesOutTheFloorsCategoryFallsThroughIt) {
    BodyId ghost = world.createBody({.x = 0, .y = -5, .hw = 5, .hh = 5, .mask = ~1u});
    run(60);
    EXPECT_GT(world.position(ghost).y, 100.0f); // fell through the floor (top at 0)
}

TEST_P(BothModels, BothSidesMustAgree) {
    // The ghost's category is in the floor's mask, but the floor's (1) is not in the
    // ghost's: no collision.
    BodyId ghost = world.createBody(
        {.x = 0, .y = -5, .hw = 5, .hh = 5, .category = kGhosts, .mask = kPlayers});
    run(60);
    EXPECT_GT(world.position(ghost).y, 100.0f);
}

TEST_P(BothModels, BodiesOfCategoriesThatAcceptEachOtherCollide) {
    BodyId box = world.createBody(
        {.x = 0, .y = -5, .hw = 5, .hh = 5, .category = kPlayers, .mask = 1 | kPlayers});
    run(60);
    EXPECT_NEAR(world.position(box).y, -5.0f, 0.1f); // resting on the floor
}

TEST_P(BothModels, TeamMatesPassThroughEachOther) {
    BodyId a = world.createBody(
        {.x = 0, .y = -5, .hw = 5, .hh = 5, .category = kPlayers, .mask = ~kPlayers});
    BodyId b = world.createBody(
        {.x = 0, .y = -30, .hw = 5, .hh = 5, .category = kPlayers, .mask = ~kPlayers});
    run(120);
    // Both on the floor, one inside the other.
    EXPECT_NEAR(world.position(a).y, -5.0f, 0.1f);
    EXPECT_NEAR(world.position(b).y, -5.0f, 0.1f);
}

TEST_P(BothModels, ASensorReportsOverlapsAndPushesNothing) {
    BodyId zone = world.createBody(
        {.type = BodyType::Static, .x = 0, .y = -100, .hw = 20, .hh = 20, .sensor = true});
    BodyId box = world.createBody({.x = 0, .y = -300, .hw = 5, .hh = 5});
    int begins = 0, ends = 0;
    float speedInside = 0;
    for (int i = 0; i < 120; ++i) {
        world.step(kDt);
        for (const SensorEvent& e : world.sensorBegins()) {
            EXPECT_EQ(e.sensor, zone);
            EXPECT_EQ(e.visitor, box);
            ++begins;
            speedInside = world.velocity(box).y;
        }
        for (const SensorEvent& e : world.sensorEnds()) {
            EXPECT_EQ(e.sensor, zone);
            EXPECT_EQ(e.visitor, box);
            ++ends;
            // The zone did not slow it: it falls as from 300 - 125 = 175 units up and more.
            EXPECT_GE(world.velocity(box).y, speedInside);
        }
    }
    EXPECT_EQ(begins, 1);
    EXPECT_EQ(ends, 1);
    EXPECT_NEAR(world.position(box).y, -5.0f, 0.1f); // landed on the floor below
}

/// Counts the begins and ends of `sensor` with `visitor` over `steps` steps, calling
/// move(step) before each.
template <class Move>
std::pair<int, int> sensorEvents(World& world, BodyId sensor, BodyId visitor, int steps,
                                 Move&& move) {
    int begins = 0, ends = 0;
    for (int i = 0; i < steps; ++i) {
        move(i);
        world.step(kDt);
        for (const SensorEvent& e : world.sensorBegins())
            begins += e.sensor == sensor && e.visitor == visitor;
        for (const SensorEvent& e : world.sensorEnds())
            ends += e.sensor == sensor && e.visitor == visitor;
    }
    return {begins, ends};
}

TEST_P(BothModels, ASensorSeesAKinematicBodyMovedByItsVelocity) {
    // A coin 100 units to the right of a kinematic character moving at 120/s: the
    // character (hw 5) reaches it (hw 5) after 90 units, 0.75 s, and leaves it 20 units
    // later; two seconds cover both.
    for (BodyType sensorType : {BodyType::Static, BodyType::Kinematic}) {
        BodyId coin = world.createBody(
            {.type = sensorType, .x = 100, .y = -100, .hw = 5, .hh = 5, .sensor = true});
        BodyId character = world.createBody(
            {.type = BodyType::Kinematic, .x = 0, .y = -100, .hw = 5, .hh = 5, .vx = 120});
        EXPECT_EQ(sensorEvents(world, coin, character, 120, [](int) {}), std::make_pair(1, 1))
            << toString(sensorType) << " sensor";
        world.destroyBody(coin);
        world.destroyBody(character);
    }
}

TEST_P(BothModels, ASensorSeesAKinematicBodyMovedByHand) {
    // The docs' character: a kinematic body at rest, moved by setPosition 2 units a step.
    BodyId coin = world.createBody(
        {.type = BodyType::Static, .x = 100, .y = -100, .hw = 5, .hh = 5, .sensor = true});
    BodyId character =
        world.createBody({.type = BodyType::Kinematic, .x = 0, .y = -100, .hw = 5, .hh = 5});
    const auto [begins, ends] = sensorEvents(world, coin, character, 120, [&](int step) {
        world.setPosition(character, {2.0f * float(step), -100});
    });
    EXPECT_EQ(begins, 1);
    EXPECT_EQ(ends, 1);
}

INSTANTIATE_TEST_SUITE_P(Models, BothModels, ::testing::Values(Solver::Classic, Solver::Physical),
                         [](const ::testing::TestParamInfo<Solver>& model) {
                             return model.param == Solver::Classic ? "Classic" : "Physical";
                         });

TEST(Filtering, TheSweepOfAFastBodyRespectsFilters) {
    // 30,000 units/s through a wall it does not collide with: not stopped by the sweep.
    World world(WorldDef{.sleeping = false});
    world.createBody({.type = BodyType::Static, .x = 1000, .y = 0, .hw = 1, .hh = 100});
    BodyId ghost = world.createBody({.x = 0, .y = 0, .hw = 2, .hh = 2, .vx = 30000, .mask = ~1u});
    for (int i = 0; i < 4; ++i)
        world.step(kDt);
    EXPECT_GT(world.position(ghost).x, 1001.0f);
}

TEST(Filtering, SettersChangeTheFilter) {
    World world(WorldDef{.gravity = {0, 800}});
    world.createBody({.type = BodyType::Static, .x = 0, .y = 50, .hw = 1000, .hh = 50});
    BodyId box = world.createBody({.x = 0, .y = -5, .hw = 5, .hh = 5});
    for (int i = 0; i < 120; ++i) // at rest, probably asleep
        world.step(kDt);
    world.setMask(box, 0);
    EXPECT_EQ(world.mask(box), 0u);
    for (int i = 0; i < 60; ++i)
        world.step(kDt);
    EXPECT_GT(world.position(box).y, 100.0f); // woken, and fell through
}

} // namespace
} // namespace jostle
