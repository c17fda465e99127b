// move(): a body moved by hand, bump.lua's way. The cases are those bump.lua's spec suite
// pins down, in jostle's terms (bump gives a rect's top-left corner and size; jostle a
// centre and half extents), plus the places where jostle's rules differ on purpose.
#include "jostle/query.hpp"
#include "jostle/tilemap.hpp"
#include "jostle/world.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace jostle {
namespace {

/// A box given as bump gives it: top-left corner (x, y), width and height.
BodyDef rect(float x, float y, float w, float h, BodyType type = BodyType::Static) {
    return {.type = type, .x = x + w / 2, .y = y + h / 2, .hw = w / 2, .hh = h / 2};
}

struct MoveTest : ::testing::Test {
    World world{WorldDef{.gravity = {0, 0}}};
    /// The item moved: (0, 0, 1, 1), a kinematic body at rest.
    BodyId item = world.createBody(rect(0, 0, 1, 1, BodyType::Kinematic));

    static MoveFilter always(Response response) {
        return [response](BodyId) { return response; };
    }
};

TEST_F(MoveTest, InAnEmptyWorldTheBodyGoesAllTheWay) {
    const MoveOutcome out = move(world, item, {1, 1});
    EXPECT_EQ(out.centre, (Vec2{1.5f, 1.5f}));
    EXPECT_TRUE(out.collisions.empty());
    EXPECT_EQ(world.position(item), out.centre);
}

TEST_F(MoveTest, TouchStopsWhereTheBodiesMeet) {
    const BodyId b = world.createBody(rect(0, 2, 1, 1));
    world.createBody(rect(0, 3, 1, 1));
    const MoveOutcome out = move(world, item, {0, 5}, always(Response::Touch));
    // Its bottom (1) reaches b's top (2) after 1 of 5.
    EXPECT_EQ(out.centre, (Vec2{0.5f, 1.5f}));
    ASSERT_EQ(out.collisions.size(), 1u);
    EXPECT_EQ(out.collisions[0].other, b);
    EXPECT_EQ(out.collisions[0].response, Response::Touch);
    EXPECT_EQ(out.collisions[0].normal, (Vec2{0, -1}));
    EXPECT_EQ(out.collisions[0].touch, (Vec2{0.5f, 1.5f}));
    EXPECT_FLOAT_EQ(out.collisions[0].time, 0.2f);
    EXPECT_EQ(out.collisions[0].otherCentre, (Vec2{0.5f, 2.5f}));
    EXPECT_EQ(out.collisions[0].otherHalf, (Vec2{0.5f, 0.5f}));
    EXPECT_EQ(world.position(item), out.centre);
}

TEST_F(MoveTest, CrossGoesThroughAndReportsEachInTurn) {
    const BodyId b = world.createBody(rect(0, 2, 1, 1));
    const BodyId c = world.createBody(rect(0, 3, 1, 1));
    const MoveOutcome out = move(world, item, {0, 5}, always(Response::Cross));
    EXPECT_EQ(out.centre, (Vec2{0.5f, 5.5f}));
    ASSERT_EQ(out.collisions.size(), 2u);
    EXPECT_EQ(out.collisions[0].other, b);
    EXPECT_FLOAT_EQ(out.collisions[0].time, 0.2f);
    EXPECT_EQ(out.collisions[1].other, c);
    EXPECT_FLOAT_EQ(out.collisions[1].time, 0.4f);
    EXPECT_EQ(out.collisions[1].touch, (Vec2{0.5f, 2.5f}));
}

TEST_F(MoveTest, SlideStopsAlongTheNormalAndGoesOnAlongTheFace) {
    // b: (0, 2, 1, 2), below the item; c: (2, 1, 1, 1). Moving by (5, 5), the item meets
    // c's left face after 1 of 5 (its right edge from 1 to 2), at (1.5, 1.5), then slides
    // down the rest: to (1.5, 5.5). It passes b's corner exactly and never enters it.
    world.createBody(rect(0, 2, 1, 2));
    const BodyId c = world.createBody(rect(2, 1, 1, 1));
    const MoveOutcome out = move(world, item, {5, 5});
    EXPECT_EQ(out.centre, (Vec2{1.5f, 5.5f}));
    ASSERT_EQ(out.collisions.size(), 1u);
    EXPECT_EQ(out.collisions[0].other, c);
    EXPECT_EQ(out.collisions[0].response, Response::Slide);
    EXPECT_EQ(out.collisions[0].normal, (Vec2{-1, 0}));
    EXPECT_EQ(out.collisions[0].touch, (Vec2{1.5f, 1.5f}));
    EXPECT_FLOAT_EQ(out.collisions[0].time, 0.2f);
}

TEST_F(MoveTest, BounceTurnsTheRestOfTheMoveBack) {
    // Down 5 onto b's top after 1: the 4 left go back up, from 1.5 to -2.5.
    world.createBody(rect(0, 2, 1, 2));
    const MoveOutcome out = move(world, item, {0, 5}, always(Response::Bounce));
    EXPECT_EQ(out.centre, (Vec2{0.5f, -2.5f}));
    ASSERT_EQ(out.collisions.size(), 1u);
    EXPECT_EQ(out.collisions[0].touch, (Vec2{0.5f, 1.5f}));
}

// Found by fuzz_api (tests/fuzz/corpus/api/move-bounces-past-the-edge-1): a move that
// keeps the body within the range of math.hpp bounced it back past the edge of that range,
// and move threw setPosition's error. It stops at the edge, as a step stops a body there.
// Near 1e9 floats are 64 apart: every number here is a multiple of 64.
TEST_F(MoveTest, ABounceBackPastTheEdgeOfTheWorldStopsThere) {
    const BodyId box =
        world.createBody({.type = BodyType::Kinematic, .x = 999999872.0f, .hw = 1024, .hh = 1024});
    // A wall whose right face is 64 left of the box's left face.
    world.createBody({.type = BodyType::Static, .x = 999997760.0f, .hw = 1024, .hh = 1024});
    // 64 to the wall, then the 236 left of 300 back to the right: 1,000,000,044, past 1e9.
    const MoveOutcome out = move(world, box, {-300, 0}, always(Response::Bounce));
    EXPECT_EQ(out.centre, (Vec2{1e9f, 0.0f}));
    EXPECT_EQ(world.position(box), (Vec2{1e9f, 0.0f}));
    ASSERT_EQ(out.collisions.size(), 1u);
}

TEST_F(MoveTest, AFloorAndAWallMetTogetherAreBothReported) {
    // A 10 × 10 item moving by (20, 20) meets a floor (top 20) and a wall (left 20) after
    // half of it: both stop it there, reported in creation order.
    const BodyId big = world.createBody(rect(0, 0, 10, 10, BodyType::Kinematic));
    const BodyId floor = world.createBody(rect(-20, 20, 100, 10));
    const BodyId wall = world.createBody(rect(20, -40, 10, 60));
    const MoveOutcome out = move(world, big, {20, 20});
    EXPECT_EQ(out.centre, (Vec2{15, 15}));
    ASSERT_EQ(out.collisions.size(), 2u);
    EXPECT_EQ(out.collisions[0].other, floor);
    EXPECT_EQ(out.collisions[1].other, wall);
    EXPECT_FLOAT_EQ(out.collisions[0].time, 0.5f);
}

TEST_F(MoveTest, NothingIsTunnelledThrough) {
    world.createBody(rect(50, -5, 1, 10));
    EXPECT_EQ(move(world, item, {100, 0}).centre, (Vec2{49.5f, 0.5f}));
}

TEST_F(MoveTest, SlidingDownAColumnOfBoxesNeverSnagsOnTheirSeams) {
    // Pressed into a column of 10 × 10 boxes (x from 0) while falling past three seams.
    const BodyId player = world.createBody(rect(-10, -30, 10, 10, BodyType::Kinematic));
    const BodyId first = world.createBody(rect(0, -20, 10, 10));
    world.createBody(rect(0, -10, 10, 10));
    world.createBody(rect(0, 0, 10, 10));
    const MoveOutcome out = move(world, player, {2, 35});
    EXPECT_EQ(out.centre, (Vec2{-5, 10}));
    ASSERT_EQ(out.collisions.size(), 1u);
    EXPECT_EQ(out.collisions[0].other, first);
}

TEST_F(MoveTest, ABodyStartingInsideAnotherIsFreeToLeave) {
    // bump.lua pushes such an item out by the shortest way first (to (3, -2) here); jostle
    // lets it go where it was going: queryBox tells that it was inside.
    const BodyId inside = world.createBody(rect(3, 3, 2, 2, BodyType::Kinematic));
    world.createBody(rect(0, 0, 8, 8));
    const MoveOutcome out = move(world, inside, {0, 17});
    EXPECT_EQ(out.centre, (Vec2{4, 21}));
    EXPECT_TRUE(out.collisions.empty());
}

TEST_F(MoveTest, TheFilterIsAskedOnceABodyAndIgnoreMeansThrough) {
    const BodyId ghost = world.createBody(rect(3, 0, 1, 1));
    const BodyId wall = world.createBody(rect(6, 0, 1, 1));
    std::map<std::uint32_t, int> asked;
    const MoveOutcome out = move(world, item, {10, 0}, [&](BodyId other) {
        ++asked[other.index];
        return other == ghost ? Response::Ignore : Response::Slide;
    });
    EXPECT_EQ(out.centre, (Vec2{5.5f, 0.5f}));
    ASSERT_EQ(out.collisions.size(), 1u);
    EXPECT_EQ(out.collisions[0].other, wall);
    for (const auto& [slot, times] : asked)
        EXPECT_EQ(times, 1) << slot;
}

TEST_F(MoveTest, SensorsAreCrossedAndFiltersAreTheBodys) {
    // By default a sensor is crossed and reported; a body the item's mask leaves out is
    // not met at all.
    const BodyId coin = world.createBody(
        {.type = BodyType::Static, .x = 3.5f, .y = 0.5f, .hw = 0.5f, .hh = 0.5f, .sensor = true});
    world.createBody(
        {.type = BodyType::Static, .x = 6.5f, .y = 0.5f, .hw = 0.5f, .hh = 0.5f, .category = 4});
    world.setMask(item, ~4u);
    const MoveOutcome out = move(world, item, {10, 0});
    EXPECT_EQ(out.centre, (Vec2{10.5f, 0.5f}));
    ASSERT_EQ(out.collisions.size(), 1u);
    EXPECT_EQ(out.collisions[0].other, coin);
    EXPECT_EQ(out.collisions[0].response, Response::Cross);
}

TEST_F(MoveTest, AMoveThatEndsTouchingASensorCrossesItOnceInTheMoveThatEntersIt) {
    // bump.lua meets a body only before the end of a move. The item's right side (1)
    // reaches the coin's left (3) at the very end of a move of 2: no crossing yet; the next
    // move enters it (one cross, at its start); the one after starts inside it (none).
    const BodyId coin = world.createBody(
        {.type = BodyType::Static, .x = 3.5f, .y = 0.5f, .hw = 0.5f, .hh = 0.5f, .sensor = true});
    EXPECT_TRUE(move(world, item, {2, 0}).collisions.empty());
    EXPECT_EQ(world.position(item), (Vec2{2.5f, 0.5f}));
    const MoveOutcome enters = move(world, item, {0.5f, 0});
    ASSERT_EQ(enters.collisions.size(), 1u);
    EXPECT_EQ(enters.collisions[0].other, coin);
    EXPECT_EQ(enters.collisions[0].time, 0.0f);
    EXPECT_TRUE(move(world, item, {0.25f, 0}).collisions.empty());
}

TEST_F(MoveTest, AMoveThatEndsTouchingAWallStopsThereAndMeetsItInTheNextMove) {
    const BodyId wall = world.createBody(rect(3, -5, 1, 10));
    EXPECT_TRUE(move(world, item, {2, 0}).collisions.empty());
    EXPECT_EQ(world.position(item), (Vec2{2.5f, 0.5f}));
    const MoveOutcome pushes = move(world, item, {1, 1});
    ASSERT_EQ(pushes.collisions.size(), 1u);
    EXPECT_EQ(pushes.collisions[0].other, wall);
    EXPECT_EQ(pushes.collisions[0].time, 0.0f);
    EXPECT_EQ(pushes.centre, (Vec2{2.5f, 1.5f})); // slid along it
}

TEST_F(MoveTest, AOneWayPlatformStopsOnlyFromItsBlockingSide) {
    world.createBody(
        {.type = BodyType::Static, .x = 0.5f, .y = -5, .hw = 5, .hh = 0.5f, .oneWay = {0, -1}});
    // Up through it from below, then down onto its top.
    EXPECT_EQ(move(world, item, {0, -10}).centre, (Vec2{0.5f, -9.5f}));
    const MoveOutcome down = move(world, item, {0, 10});
    EXPECT_EQ(down.centre, (Vec2{0.5f, -6}));
    ASSERT_EQ(down.collisions.size(), 1u);
}

TEST_F(MoveTest, BadArgumentsThrow) {
    EXPECT_THROW(move(world, item, {NAN, 0}), Error);
    EXPECT_THROW(move(world, item, {2e9f, 0}), Error);
    world.destroyBody(item);
    EXPECT_THROW(move(world, item, {1, 0}), Error);
}

// Issue 28: a filter that changed the world freed what the walk was reading (a filter that
// created a body: use-after-free in the candidates; one that destroyed the world: in the
// cast). Every call that changes the world now throws from a filter, as in C and Lua.
TEST_F(MoveTest, EveryCallThatChangesTheWorldIsRefusedFromTheFilter) {
    const BodyId wall = world.createBody(rect(3, 0, 1, 1));
    const std::vector<std::function<void()>> changes = {
        [&] { world.createBody(rect(10, 10, 1, 1)); },
        [&] { world.destroyBody(wall); },
        [&] {
            world.setPosition(wall, {5, 5});
        },
        [&] {
            world.setVelocity(item, {1, 0});
        },
        [&] {
            world.setHalfExtents(wall, {2, 2});
        },
        [&] { world.setBounce(wall, 0.5f); },
        [&] { world.setType(wall, BodyType::Kinematic); },
        [&] { world.setUserData(wall, nullptr); },
        [&] { world.setBullet(item, true); },
        [&] { world.setSensor(wall, true); },
        [&] { world.setWalkSpeed(item, 1); },
        [&] { world.wake(wall); },
        [&] {
            world.applyImpulse(item, {1, 0});
        },
        [&] {
            world.setGravity({0, 1});
        },
        [&] { world.step(1.0f / 60); },
        [&] {
            move(world, wall, {1, 0});
        },
        [&] { createTileMap(world, {.tile = 1, .rows = {"#"}}); },
    };
    for (std::size_t k = 0; k < changes.size(); ++k) {
        std::string message;
        const MoveOutcome out = move(world, item, {5, 0}, [&](BodyId) {
            try {
                changes[k]();
            } catch (const Error& e) {
                message = e.what();
            }
            return Response::Slide;
        });
        EXPECT_NE(message.find("called from move()'s filter"), std::string::npos)
            << "change " << k << ": " << message;
        // Nothing changed: the wall is where it was, and stops the move.
        EXPECT_EQ(out.centre, (Vec2{2.5f, 0.5f})) << "change " << k;
        ASSERT_TRUE(world.isValid(wall));
        EXPECT_EQ(world.position(wall), (Vec2{3.5f, 0.5f}));
        world.setPosition(item, {0.5f, 0.5f});
    }
    // Reading is allowed, and once the move is done the world changes again.
    move(world, item, {1, 0}, [&](BodyId other) {
        EXPECT_EQ(world.position(other), (Vec2{3.5f, 0.5f}));
        return Response::Slide;
    });
    world.createBody(rect(10, 10, 1, 1));
    EXPECT_EQ(world.bodyCount(), 3u);
}

// The attack's case: move() called from a pre-solve, with a filter that creates bodies.
TEST(MoveFromACallback, AFilterCreatingBodiesFromAPreSolveIsRefusedAndTheStepGoesOn) {
    World world(WorldDef{.gravity = {0, 100}});
    world.createBody({.type = BodyType::Static, .x = 0, .y = 2, .hw = 50, .hh = 1});
    world.createBody({.x = 0, .y = 0.5f, .hw = 1, .hh = 1});
    const BodyId mover = world.createBody(rect(-20, -20, 1, 1, BodyType::Kinematic));
    world.createBody(rect(-10, -20, 1, 1));
    int refused = 0;
    world.setPreSolve([&](Collision&) {
        move(world, mover, {20, 0}, [&](BodyId) {
            try {
                for (int i = 0; i < 100; ++i)
                    world.createBody(rect(float(i) * 3, -40, 1, 1));
            } catch (const Error&) {
                ++refused;
            }
            return Response::Slide;
        });
        return true;
    });
    for (int i = 0; i < 5; ++i)
        world.step(1.0f / 60);
    EXPECT_GT(refused, 0);
    EXPECT_EQ(world.bodyCount(), 4u);
}

// Destroying the world from a filter cannot throw (a destructor): it stops the program
// with a message, as destroying it from a step's callback does.
TEST(MoveFromACallbackDeathTest, DestroyingTheWorldFromTheFilterStopsWithAMessage) {
    EXPECT_DEATH(
        {
            auto world = std::make_unique<World>(WorldDef{});
            const BodyId item = world->createBody(rect(0, 0, 1, 1, BodyType::Kinematic));
            world->createBody(rect(3, 0, 1, 1));
            move(*world, item, {5, 0}, [&](BodyId) {
                world.reset();
                return Response::Slide;
            });
        },
        "World destroyed from a callback during move");
}

} // namespace
} // namespace jostle
