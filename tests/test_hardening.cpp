// Defects an attack on every surface found (issue 19), each as the smallest case that
// shows it: callbacks that create and destroy bodies mid-step, and scenes that pile bodies
// at one spot.
#include "jostle/tilemap.hpp"
#include "jostle/world.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace jostle {
namespace {

constexpr float kDt = 1.0f / 60.0f;

std::size_t contactCount(const World& world) {
    std::size_t count = 0;
    for (BodyId id : world.bodies())
        count += world.contacts(id).size();
    return count / 2; // each contact is listed by both of its bodies
}

class EitherModel : public ::testing::TestWithParam<Solver> {};

// The attack's case: a pre-solve creates a static body where a dynamic body resolved later
// in the same step overlaps it.
TEST_P(EitherModel, PreSolveCreatingAStaticBodyInTheWayOfALaterBody) {
    World world(WorldDef{.gravity = {0, 100}, .solver = GetParam()});
    world.createBody({.type = BodyType::Static, .x = 0, .y = 2, .hw = 50, .hh = 1});
    world.createBody({.x = 0, .y = 0.5f, .hw = 1, .hh = 1});
    const BodyId later = world.createBody({.x = 10, .y = -5, .hw = 1, .hh = 1});
    bool made = false;
    world.setPreSolve([&](Collision&) {
        if (!made) {
            made = true;
            world.createBody({.type = BodyType::Static, .x = 10, .y = -5, .hw = 1, .hh = 1});
        }
        return true;
    });
    for (int i = 0; i < 10; ++i)
        world.step(kDt);
    EXPECT_TRUE(made);
    EXPECT_TRUE(std::isfinite(world.position(later).y));
}

// Every type of body created, and bodies destroyed, from inside each pre-solve call, in a
// crowd that keeps calling it: the step carries on with the world as the callback left it.
TEST_P(EitherModel, PreSolveCreatesAndDestroysBodiesOfEveryType) {
    World world(WorldDef{.gravity = {0, 400}, .solver = GetParam()});
    world.createBody({.type = BodyType::Static, .x = 0, .y = 40, .hw = 200, .hh = 4});
    for (int i = 0; i < 40; ++i)
        world.createBody({.x = float(i % 8) * 3.0f - 12.0f,
                          .y = 30.0f - float(i / 8) * 2.5f,
                          .hw = 1.2f,
                          .hh = 1.2f});
    std::vector<BodyId> made;
    int calls = 0;
    const BodyType types[] = {BodyType::Static, BodyType::Kinematic, BodyType::Dynamic};
    world.setPreSolve([&](Collision& c) {
        ++calls;
        const BodyType type = types[calls % 3];
        made.push_back(world.createBody({.type = type,
                                         .x = world.position(c.a).x,
                                         .y = world.position(c.a).y,
                                         .hw = 1,
                                         .hh = 1,
                                         .vx = type == BodyType::Kinematic ? 5.0f : 0.0f}));
        if (calls % 4 == 0) {
            if (world.isValid(made.front()))
                world.destroyBody(made.front());
            made.erase(made.begin());
        }
        if (calls % 7 == 0 && world.isValid(c.b) && world.type(c.b) == BodyType::Dynamic)
            world.destroyBody(c.b);
        return calls % 5 != 0;
    });
    for (int i = 0; i < 30 && world.bodyCount() < 3000; ++i)
        world.step(kDt);
    EXPECT_GT(calls, 100);
    for (BodyId id : world.bodies()) {
        EXPECT_TRUE(std::isfinite(world.position(id).x));
        EXPECT_TRUE(std::isfinite(world.position(id).y));
    }
}

INSTANTIATE_TEST_SUITE_P(Hardening, EitherModel,
                         ::testing::Values(Solver::Classic, Solver::Physical));

// Issue 28: a pre-solve that creates a body (or sets a tile) while another body sleeps
// rebuilds the resting grid mid-step; a fast body's sweep then met the new body, whose slot
// was past the step's per-slot tables (heap overflow under ASan).
enum class Maker { StaticBox, Circle, SolidTile };

class MadeWhileOneSleeps : public ::testing::TestWithParam<Maker> {};

TEST_P(MadeWhileOneSleeps, InTheWayOfAFastBodyIsMetBySweepWithoutOverflow) {
    WorldDef def;
    def.gravity = {0, 800};
    World world(def);
    world.createBody({.type = BodyType::Static, .x = 0, .y = 100, .hw = 1000, .hh = 10});
    const BodyId sleeper = world.createBody({.x = -500, .y = 85, .hw = 5, .hh = 5});
    const BodyId a = world.createBody({.x = 0, .y = 85, .hw = 5, .hh = 5});
    // An empty map around the fast body's path, made before anything sleeps.
    const TileMapId map = createTileMap(world, {.x = 140, .y = 40, .tile = 20, .rows = {".."}});
    for (int s = 0; s < 120; ++s)
        world.step(1.0f / 60);
    ASSERT_FALSE(world.isAwake(sleeper));
    world.wake(a);
    const BodyId fast =
        world.createBody({.x = 100, .y = 50, .hw = 5, .hh = 5, .vx = 6000, .gravityScale = 0});
    bool once = false;
    world.setPreSolve([&](Collision&) {
        if (!once) {
            once = true;
            switch (GetParam()) {
            case Maker::StaticBox:
                world.createBody({.type = BodyType::Static, .x = 150, .y = 50, .hw = 10, .hh = 10});
                break;
            case Maker::Circle:
                world.createBody({.type = BodyType::Static,
                                  .x = 150,
                                  .y = 50,
                                  .hw = 10,
                                  .hh = 10,
                                  .radius = 10});
                break;
            case Maker::SolidTile:
                setTile(world, map, 0, 0, true);
                break;
            }
        }
        return true;
    });
    world.step(1.0f / 60);
    EXPECT_TRUE(once);
    // The fast body stops at what was made in its path (its left face, x = 140), within
    // what position correction leaves of an overlap in one step: it does not pass through.
    EXPECT_NEAR(world.position(fast).x, 140.0f - 5.0f, 0.5f);
    EXPECT_TRUE(std::isfinite(world.position(sleeper).y));
}

INSTANTIATE_TEST_SUITE_P(Hardening, MadeWhileOneSleeps,
                         ::testing::Values(Maker::StaticBox, Maker::Circle, Maker::SolidTile));

// 1,000 boxes at one spot make half a million overlapping pairs; a step kept a contact for each
// (10,000 such boxes took 8 GB). Each dynamic body now has a budget of contacts.
TEST(ContactBudget, BoxesPiledAtOneSpotKeepABoundedNumberOfContacts) {
    World world(WorldDef{.gravity = {0, 10}});
    world.createBody({.type = BodyType::Static, .x = 0, .y = 1, .hw = 3000, .hh = 1});
    constexpr int kBoxes = 1000;
    for (int i = 0; i < kBoxes; ++i)
        world.createBody({.x = 0, .y = -0.5f, .hw = 0.5f, .hh = 0.5f});
    world.step(kDt);
    const int budget = PhysicalOptions{}.maxContactsPerBody;
    // Each box: at most `budget` moving neighbours (each pair counted by both) and as many
    // resting ones (here only the ground).
    EXPECT_LE(contactCount(world), std::size_t(kBoxes) * std::size_t(budget) / 2 + kBoxes);
    EXPECT_GT(world.pairsLeftOut(), 400'000u);
    for (int i = 0; i < 60; ++i)
        world.step(kDt);
    for (BodyId id : world.bodies())
        EXPECT_TRUE(std::isfinite(world.position(id).y));
}

// The crowd's pairs are counted apart from the ground's: however crowded a box is, it
// keeps its floor and never falls through it.
TEST(ContactBudget, ACrowdNeverCrowdsOutTheFloor) {
    World world(WorldDef{.gravity = {0, 10}, .physical = {.maxContactsPerBody = 4}});
    world.createBody({.type = BodyType::Static, .x = 0, .y = 1, .hw = 100, .hh = 1});
    for (int i = 0; i < 50; ++i)
        world.createBody({.x = float(i % 5) * 0.1f, .y = -0.5f, .hw = 0.5f, .hh = 0.5f});
    for (int i = 0; i < 120; ++i) {
        world.step(kDt);
        for (BodyId id : world.bodies()) {
            if (world.type(id) == BodyType::Dynamic) {
                ASSERT_LT(world.position(id).y, 0.0f) << "step " << i;
            }
        }
    }
}

TEST(ContactBudget, ASaneSceneLeavesNothingOut) {
    World world(WorldDef{.gravity = {0, 10}});
    world.createBody({.type = BodyType::Static, .x = 0, .y = 1, .hw = 100, .hh = 1});
    for (int row = 0; row < 20; ++row)
        for (int i = 0; i < 20 - row; ++i)
            world.createBody({.x = float(i) - 0.5f * float(19 - row),
                              .y = -0.5f - float(row),
                              .hw = 0.5f,
                              .hh = 0.5f});
    for (int i = 0; i < 120; ++i) {
        world.step(kDt);
        ASSERT_EQ(world.pairsLeftOut(), 0u);
    }
}

TEST(ContactBudget, MustBeAtLeastOne) {
    EXPECT_TRUE(checkWorldDef(WorldDef{.physical = {.maxContactsPerBody = 0}}).has_value());
    EXPECT_TRUE(checkWorldDef(WorldDef{.physical = {.maxContactsPerBody = 65537}}).has_value());
    EXPECT_FALSE(checkWorldDef(WorldDef{.physical = {.maxContactsPerBody = 1}}).has_value());
}

} // namespace
} // namespace jostle
