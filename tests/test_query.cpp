// Queries (jostle/query.hpp): points, boxes, rays, box casts and moveAndSlide, their
// filters, their edge cases, their order, and agreement with brute force on random worlds.
#include "jostle/query.hpp"

#include "jostle/world.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <thread>
#include <vector>

namespace jostle {
namespace {

constexpr float kDt = 1.0f / 60.0f;
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

BodyDef wall(float x, float y, float hw, float hh) {
    return {.type = BodyType::Static, .x = x, .y = y, .hw = hw, .hh = hh};
}

/// A world without gravity: bodies stay where they are put.
struct Still {
    World world{WorldDef{}};
};

// --- queryPoint, queryBox, queryRect -----------------------------------------------------

TEST(QueryPoint, FindsTheBodiesContainingThePointInCreationOrder) {
    Still s;
    BodyId big = s.world.createBody(wall(0, 0, 50, 50));
    BodyId small = s.world.createBody({.x = 5, .y = 5, .hw = 10, .hh = 10});
    BodyId far = s.world.createBody(wall(200, 0, 10, 10));
    EXPECT_EQ(queryPoint(s.world, {5, 5}), (std::vector<BodyId>{big, small}));
    EXPECT_EQ(queryPoint(s.world, {-40, 0}), (std::vector<BodyId>{big}));
    EXPECT_EQ(queryPoint(s.world, {200, 0}), (std::vector<BodyId>{far}));
    EXPECT_TRUE(queryPoint(s.world, {100, 0}).empty());
}

TEST(QueryPoint, APointOnTheSeamBetweenTwoTilesIsOnBoth) {
    Still s;
    BodyId left = s.world.createBody(wall(-8, 0, 8, 8)); // x in [-16, 0]
    BodyId right = s.world.createBody(wall(8, 0, 8, 8)); // x in [0, 16]
    EXPECT_EQ(queryPoint(s.world, {0, 3}), (std::vector<BodyId>{left, right}));
    EXPECT_EQ(queryPoint(s.world, {16, 8}), (std::vector<BodyId>{right})); // a corner
    EXPECT_TRUE(queryPoint(s.world, {16.001f, 0}).empty());
}

TEST(QueryBox, ReportsBodiesSharingAreaNotThoseTouchingEdgeToEdge) {
    Still s;
    BodyId floor = s.world.createBody(wall(0, 10, 100, 10)); // top at y = 0
    BodyId crate = s.world.createBody({.x = 30, .y = -5, .hw = 5, .hh = 5});
    // A box resting exactly on the floor, beside the crate (whose left edge is x = 25):
    // it touches both and overlaps neither. "Is there room to stand here?" Yes.
    EXPECT_TRUE(queryBox(s.world, {15, -10}, {10, 10}).empty());
    // One unit lower, and one to the right: it overlaps both.
    EXPECT_EQ(queryBox(s.world, {16, -9}, {10, 10}), (std::vector<BodyId>{floor, crate}));
    EXPECT_EQ(queryRect(s.world, {6, -19}, {26, 1}), (std::vector<BodyId>{floor, crate}));
    EXPECT_EQ(queryRect(s.world, {5, -20}, {25, 0}), std::vector<BodyId>{});
}

TEST(QueryBox, AZeroSizeBoxFindsTheBodiesWhoseInsideHoldsIt) {
    Still s;
    BodyId a = s.world.createBody(wall(0, 0, 10, 10));
    EXPECT_EQ(queryBox(s.world, {3, 3}, {0, 0}), (std::vector<BodyId>{a}));
    EXPECT_TRUE(queryBox(s.world, {10, 3}, {0, 0}).empty()); // on the edge: no area inside
}

TEST(QueryBox, TheOutVariantsClearAndRefill) {
    Still s;
    BodyId a = s.world.createBody(wall(0, 0, 10, 10));
    std::vector<BodyId> out{BodyId{7, 7}};
    queryBox(s.world, {0, 0}, {1, 1}, {}, out);
    EXPECT_EQ(out, (std::vector<BodyId>{a}));
    queryRect(s.world, {50, 50}, {60, 60}, {}, out);
    EXPECT_TRUE(out.empty());
    queryPoint(s.world, {0, 0}, {}, out);
    EXPECT_EQ(out, (std::vector<BodyId>{a}));
}

TEST(QueryOrder, IsCreationOrderEvenWhenSlotsAreReused) {
    Still s;
    BodyId first = s.world.createBody(wall(0, 0, 10, 10));
    BodyId doomed = s.world.createBody(wall(1, 0, 10, 10));
    BodyId second = s.world.createBody({.x = 2, .y = 0, .hw = 10, .hh = 10});
    s.world.destroyBody(doomed);
    // Reuses doomed's slot (a smaller index than second's) but is created last.
    BodyId third = s.world.createBody({.x = 3, .y = 0, .hw = 10, .hh = 10});
    ASSERT_LT(third.index, second.index);
    EXPECT_EQ(queryPoint(s.world, {0, 0}), (std::vector<BodyId>{first, second, third}));
    std::vector<RayHit> hits = rayCastAll(s.world, {0, -50}, {0, 50});
    ASSERT_EQ(hits.size(), 3u); // all three entered at the same fraction: creation order
    EXPECT_EQ(hits[0].body, first);
    EXPECT_EQ(hits[1].body, second);
    EXPECT_EQ(hits[2].body, third);
}

// --- Filters -----------------------------------------------------------------------------

constexpr std::uint32_t kLevel = 1, kPlayer = 2, kEnemy = 4;

struct Crowd {
    World world{WorldDef{}};
    // All four on the point (0, 0).
    BodyId ground = world.createBody(wall(0, 0, 20, 20));
    BodyId player = world.createBody(
        {.x = 0, .y = 0, .hw = 5, .hh = 5, .category = kPlayer, .mask = kLevel | kEnemy});
    BodyId enemy = world.createBody(
        {.x = 0, .y = 0, .hw = 5, .hh = 5, .category = kEnemy, .mask = kLevel | kPlayer});
    BodyId zone = world.createBody(
        {.type = BodyType::Static, .x = 0, .y = 0, .hw = 30, .hh = 30, .sensor = true});
};

TEST(QueryFilter, ByDefaultEveryBodyButSensors) {
    Crowd c;
    EXPECT_EQ(queryPoint(c.world, {0, 0}), (std::vector<BodyId>{c.ground, c.player, c.enemy}));
}

TEST(QueryFilter, MaskPicksTheCategoriesReported) {
    Crowd c;
    EXPECT_EQ(queryPoint(c.world, {0, 0}, {.mask = kEnemy}), (std::vector<BodyId>{c.enemy}));
    EXPECT_EQ(queryPoint(c.world, {0, 0}, {.mask = kLevel | kPlayer}),
              (std::vector<BodyId>{c.ground, c.player}));
}

TEST(QueryFilter, TheBodiesMasksMustAcceptTheQuerysCategory) {
    Crowd c;
    // A query of category kEnemy sees what an enemy would collide with: the ground (mask
    // all), the player (mask kLevel | kEnemy), not the enemy (mask kLevel | kPlayer).
    EXPECT_EQ(queryPoint(c.world, {0, 0}, {.category = kEnemy}),
              (std::vector<BodyId>{c.ground, c.player}));
    // A body of mask 0 collides with nothing, and no query sees it.
    c.world.setMask(c.ground, 0);
    EXPECT_EQ(queryPoint(c.world, {0, 0}), (std::vector<BodyId>{c.player, c.enemy}));
}

TEST(QueryFilter, SensorsOnRequest) {
    Crowd c;
    EXPECT_EQ(queryPoint(c.world, {0, 0}, {.includeSensors = true}),
              (std::vector<BodyId>{c.ground, c.player, c.enemy, c.zone}));
    EXPECT_EQ(queryPoint(c.world, {25, 25}, {.includeSensors = true}),
              (std::vector<BodyId>{c.zone}));
    EXPECT_TRUE(queryPoint(c.world, {25, 25}).empty());
    // A sensor does not block a ray unless asked.
    EXPECT_FALSE(rayCast(c.world, {-50, 25}, {50, 25}));
    std::optional<RayHit> hit = rayCast(c.world, {-50, 25}, {50, 25}, {.includeSensors = true});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->body, c.zone);
}

TEST(QueryFilter, IgnoreLeavesOutOneBody) {
    Crowd c;
    EXPECT_EQ(queryPoint(c.world, {0, 0}, {.ignore = c.player}),
              (std::vector<BodyId>{c.ground, c.enemy}));
}

TEST(QueryFilter, AStaleIgnoreIsAnError) {
    Crowd c;
    c.world.destroyBody(c.enemy);
    EXPECT_THROW(queryPoint(c.world, {0, 0}, {.ignore = c.enemy}), Error);
    EXPECT_THROW(rayCast(c.world, {0, 0}, {1, 0}, {.ignore = c.enemy}), Error);
    EXPECT_THROW(moveAndSlide(c.world, {0, 0}, {1, 1}, {1, 0}, {.ignore = c.enemy}), Error);
    // A reused slot is not the ignored body either.
    BodyId reborn = c.world.createBody(wall(0, 0, 1, 1));
    ASSERT_EQ(reborn.index, c.enemy.index);
    EXPECT_THROW(queryPoint(c.world, {0, 0}, {.ignore = c.enemy}), Error);
}

// --- Argument checks ---------------------------------------------------------------------

TEST(QueryArguments, NaNAndInfinityAreErrors) {
    Still s;
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_THROW(queryPoint(s.world, {kNaN, 0}), Error);
    EXPECT_THROW(queryBox(s.world, {0, 0}, {kNaN, 1}), Error);
    EXPECT_THROW(queryBox(s.world, {inf, 0}, {1, 1}), Error);
    EXPECT_THROW(queryRect(s.world, {0, kNaN}, {1, 1}), Error);
    EXPECT_THROW(rayCast(s.world, {0, 0}, {kNaN, 1}), Error);
    EXPECT_THROW(rayCastAll(s.world, {-inf, 0}, {1, 1}), Error);
    EXPECT_THROW(boxCast(s.world, {0, 0}, {1, 1}, {0, kNaN}), Error);
    EXPECT_THROW(moveAndSlide(s.world, {kNaN, 0}, {1, 1}, {1, 0}), Error);
    // Finite ends, but a length a float cannot hold.
    EXPECT_THROW(rayCast(s.world, {-3e38f, 0}, {3e38f, 0}), Error);
}

TEST(QueryArguments, SizesAndCornersFollowTheirRules) {
    Still s;
    EXPECT_THROW(queryBox(s.world, {0, 0}, {-1, 1}), Error);
    EXPECT_NO_THROW(queryBox(s.world, {0, 0}, {0, 0}));
    EXPECT_THROW(queryRect(s.world, {1, 0}, {0, 1}), Error);
    EXPECT_THROW(boxCast(s.world, {0, 0}, {0, 1}, {1, 0}), Error);
    EXPECT_THROW(moveAndSlide(s.world, {0, 0}, {1, -1}, {1, 0}), Error);
    try {
        queryRect(s.world, {1, 0}, {0, 1});
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "queryRect: min must be <= max on both axes");
    }
}

// --- Queries see bodies where they are now -----------------------------------------------

TEST(QueryFreshness, AFallingBodyIsFoundWhereTheStepLeftIt) {
    World world{WorldDef{.gravity = {0, 800}, .sleeping = false}};
    BodyId box = world.createBody({.x = 0, .y = 0, .hw = 5, .hh = 5, .vy = 600});
    for (int i = 0; i < 6; ++i)
        world.step(kDt);
    const Vec2 p = world.position(box);
    ASSERT_GT(p.y, 60.0f); // moved well beyond its own size
    EXPECT_EQ(queryPoint(world, p), (std::vector<BodyId>{box}));
    EXPECT_TRUE(queryPoint(world, {0, 0}).empty());
    std::optional<RayHit> hit = rayCast(world, {0, -100}, {0, 500});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->point.y, p.y - 5);
}

TEST(QueryFreshness, StaticsMovedCreatedAndDestroyedAfterAStep) {
    World world{WorldDef{.gravity = {0, 800}}};
    BodyId a = world.createBody(wall(0, 0, 10, 10));
    world.step(kDt); // the resting grid is built
    EXPECT_EQ(queryPoint(world, {0, 0}), (std::vector<BodyId>{a}));
    world.setPosition(a, {100, 0});
    EXPECT_TRUE(queryPoint(world, {0, 0}).empty());
    EXPECT_EQ(queryPoint(world, {100, 0}), (std::vector<BodyId>{a}));
    BodyId b = world.createBody(wall(0, 0, 10, 10));
    EXPECT_EQ(queryPoint(world, {0, 0}), (std::vector<BodyId>{b}));
    world.setHalfExtents(b, {1, 1});
    EXPECT_TRUE(queryPoint(world, {5, 0}).empty());
    world.destroyBody(b);
    EXPECT_TRUE(queryPoint(world, {0, 0}).empty());
    // Made kinematic: it leaves the resting grid, and queries must still find it.
    world.setType(a, BodyType::Kinematic);
    EXPECT_EQ(queryPoint(world, {100, 0}), (std::vector<BodyId>{a}));
    world.setType(a, BodyType::Static);
    EXPECT_EQ(queryPoint(world, {100, 0}), (std::vector<BodyId>{a}));
    world.setType(a, BodyType::Dynamic); // and now it falls
    world.step(kDt);
    EXPECT_EQ(queryPoint(world, world.position(a)), (std::vector<BodyId>{a}));
}

TEST(QueryFreshness, ADestroyedBodyIsGoneEvenIfAStaticBecameMobileMeanwhile) {
    Still s;
    BodyId doomed = s.world.createBody({.x = 0, .y = 0, .hw = 5, .hh = 5});
    BodyId block = s.world.createBody(wall(50, 0, 5, 5));
    EXPECT_EQ(queryPoint(s.world, {0, 0}), (std::vector<BodyId>{doomed}));
    // One body fewer outside the grid, one more: the counts alone would not tell.
    s.world.destroyBody(doomed);
    s.world.setType(block, BodyType::Kinematic);
    EXPECT_TRUE(queryPoint(s.world, {0, 0}).empty());
    EXPECT_EQ(queryPoint(s.world, {50, 0}), (std::vector<BodyId>{block}));
}

TEST(QueryFreshness, SleepingBodiesAreFoundAndSoAreTheyOnceWokenAndMoved) {
    World world{WorldDef{.gravity = {0, 800}}};
    world.createBody(wall(0, 50, 1000, 50)); // top at y = 0
    BodyId box = world.createBody({.x = 0, .y = -5, .hw = 5, .hh = 5});
    for (int i = 0; i < 120; ++i)
        world.step(kDt);
    ASSERT_FALSE(world.isAwake(box));
    EXPECT_EQ(queryPoint(world, world.position(box), {.mask = ~kLevel}).size(), 0u);
    EXPECT_EQ(queryPoint(world, world.position(box)), (std::vector<BodyId>{box}));
    world.setVelocity(box, {600, 0});
    for (int i = 0; i < 10; ++i)
        world.step(kDt);
    ASSERT_GT(world.position(box).x, 50.0f);
    EXPECT_EQ(queryBox(world, world.position(box), {1, 1}), (std::vector<BodyId>{box}));
    EXPECT_TRUE(queryBox(world, {0, -5}, {1, 1}).empty());
}

TEST(QueryFreshness, AQueryFromACallbackDuringAStepSeesTheBodies) {
    World world{WorldDef{.gravity = {0, 800}}};
    BodyId floor = world.createBody(wall(0, 50, 1000, 50));
    world.createBody({.x = 0, .y = -5, .hw = 5, .hh = 5});
    std::vector<BodyId> seen;
    world.setPreSolve([&](Collision&) {
        // Something moved a static during the step: the resting grid is out of date, and
        // the query must not rebuild it under the step's feet. The floor now covers y in
        // [10, 110], no longer [0, 100].
        world.setPosition(floor, {0, 60});
        seen = queryPoint(world, {500, 105});
        return true;
    });
    world.step(kDt);
    EXPECT_EQ(seen, (std::vector<BodyId>{floor}));
}

TEST(QueryThreads, QueriesOnSeveralThreadsAgree) {
    World world{WorldDef{}};
    for (int i = 0; i < 200; ++i)
        world.createBody(wall(float(i) * 10.0f, 0, 4, 4));
    // The first queries bring the index up to date, all at once.
    std::vector<std::vector<RayHit>> results(4);
    std::vector<std::thread> threads;
    for (auto& result : results)
        threads.emplace_back([&] { result = rayCastAll(world, {-10, 0}, {2000, 0}); });
    for (std::thread& t : threads)
        t.join();
    for (const auto& result : results) {
        ASSERT_EQ(result.size(), 200u);
        for (std::size_t i = 0; i < result.size(); ++i)
            EXPECT_EQ(result[i].body, world.bodies()[i]);
    }
}

// --- rayCast -----------------------------------------------------------------------------

/// One box, x and y in [-10, 10].
struct OneBox {
    World world{WorldDef{}};
    BodyId box = world.createBody(wall(0, 0, 10, 10));
};

TEST(RayCast, HitsTheFaceItMeets) {
    OneBox s;
    // From x = -30 to x = 10: the left face x = -10 is 20 of 40 along.
    std::optional<RayHit> hit = rayCast(s.world, {-30, 5}, {10, 5});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->body, s.box);
    EXPECT_EQ(hit->fraction, 0.5f);
    EXPECT_EQ(hit->point, (Vec2{-10, 5}));
    EXPECT_EQ(hit->normal, (Vec2{-1, 0}));
    // Upwards from below: the bottom face y = 10 is 30 of 60 along.
    hit = rayCast(s.world, {3, 40}, {3, -20});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->fraction, 0.5f);
    EXPECT_EQ(hit->point.y, 10.0f);
    EXPECT_EQ(hit->normal, (Vec2{0, 1}));
}

TEST(RayCast, FallsShortOrMisses) {
    OneBox s;
    EXPECT_FALSE(rayCast(s.world, {-30, 5}, {-10.5f, 5})); // ends before the face
    EXPECT_FALSE(rayCast(s.world, {-30, 11}, {30, 11}));   // passes above
    EXPECT_FALSE(rayCast(s.world, {30, 5}, {50, 5}));      // points away
}

TEST(RayCast, EndingExactlyOnTheFaceHitsAtOne) {
    OneBox s;
    std::optional<RayHit> hit = rayCast(s.world, {-30, 0}, {-10, 0});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->fraction, 1.0f);
}

TEST(RayCast, StartingInsideHitsAtZeroFacingTheMainDirection) {
    OneBox s;
    // Moves more along x (30) than y (10): the normal faces x, against the ray.
    std::optional<RayHit> hit = rayCast(s.world, {0, 0}, {30, 10});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->fraction, 0.0f);
    EXPECT_EQ(hit->point, (Vec2{0, 0}));
    EXPECT_EQ(hit->normal, (Vec2{-1, 0}));
    // Equal: y. Downward in a y-down world: the normal points up, like a floor's.
    hit = rayCast(s.world, {1, 1}, {11, 11});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->normal, (Vec2{0, -1}));
}

TEST(RayCast, AGroundProbeStartingInsideTheFloorReportsTheFloor) {
    // The physical model leaves a resting box up to its slop inside the floor: a probe
    // from its bottom edge starts inside the floor.
    World world{WorldDef{}};
    BodyId floor = world.createBody(wall(0, 10, 100, 10)); // top at y = 0
    std::optional<RayHit> hit = rayCast(world, {0, 0.05f}, {0, 2});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->body, floor);
    EXPECT_EQ(hit->normal, (Vec2{0, -1}));
}

TEST(RayCast, StartingOnTheEdgeHeadingInHitsAtZeroAndHeadingAwayMisses) {
    OneBox s;
    std::optional<RayHit> hit = rayCast(s.world, {-10, 0}, {10, 0});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->fraction, 0.0f);
    EXPECT_EQ(hit->normal, (Vec2{-1, 0})); // the face it starts on
    EXPECT_FALSE(rayCast(s.world, {-10, 0}, {-30, 0}));
    EXPECT_FALSE(rayCast(s.world, {10, 10}, {20, 20})); // from a corner, outwards
}

TEST(RayCast, GrazingACornerCounts) {
    OneBox s;
    // x = -20 + 20t, y = -20t: at t = 0.5 it is at the corner (-10, -10), and nowhere else
    // on the box. It enters the x slab there (the y slab it was already in): the left face.
    std::optional<RayHit> hit = rayCast(s.world, {-20, 0}, {0, -20});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->fraction, 0.5f);
    EXPECT_EQ(hit->point, (Vec2{-10, -10}));
    EXPECT_EQ(hit->normal, (Vec2{-1, 0}));
    // Straight into the corner, entering both slabs at once: the y face wins the tie.
    hit = rayCast(s.world, {-20, -20}, {0, 0});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->fraction, 0.5f);
    EXPECT_EQ(hit->point, (Vec2{-10, -10}));
    EXPECT_EQ(hit->normal, (Vec2{0, -1}));
}

TEST(RayCast, RunningAlongAFaceCounts) {
    OneBox s;
    // Along the top face y = -10, from x = -20: reaches the box at x = -10, 10 of 40.
    std::optional<RayHit> hit = rayCast(s.world, {-20, -10}, {20, -10});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->fraction, 0.25f);
    EXPECT_EQ(hit->point, (Vec2{-10, -10}));
    EXPECT_EQ(hit->normal, (Vec2{-1, 0}));
}

TEST(RayCast, DownTheSeamBetweenTwoTilesHitsTheFloorAndTheOlderTileWins) {
    World world{WorldDef{}};
    BodyId right = world.createBody(wall(8, 8, 8, 8)); // x in [0, 16], top at y = 0
    BodyId left = world.createBody(wall(-8, 8, 8, 8)); // x in [-16, 0]
    std::optional<RayHit> hit = rayCast(world, {0, -10}, {0, 10});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->body, right); // same fraction 0.5: created first
    EXPECT_EQ(hit->fraction, 0.5f);
    EXPECT_EQ(hit->normal, (Vec2{0, -1}));
    std::vector<RayHit> all = rayCastAll(world, {0, -10}, {0, 10});
    ASSERT_EQ(all.size(), 2u);
    EXPECT_EQ(all[0].body, right);
    EXPECT_EQ(all[1].body, left);
}

TEST(RayCast, AZeroLengthRayHitsNothing) {
    OneBox s;
    EXPECT_FALSE(rayCast(s.world, {0, 0}, {0, 0}));
    EXPECT_TRUE(rayCastAll(s.world, {0, 0}, {0, 0}).empty());
}

TEST(RayCast, OneWayPlatformsOnlyThroughTheirBlockingFace) {
    World world{WorldDef{}};
    BodyId ledge = world.createBody(
        {.type = BodyType::Static, .x = 0, .y = 0, .hw = 20, .hh = 2, .oneWay = {0, -1}});
    // From above: enters the top face y = -2 at (-2 + 10) / 20 = 0.4.
    std::optional<RayHit> hit = rayCast(world, {0, -10}, {0, 10});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->body, ledge);
    EXPECT_EQ(hit->fraction, 0.4f);
    EXPECT_FALSE(rayCast(world, {0, 10}, {0, -10})); // from below
    EXPECT_FALSE(rayCast(world, {-30, 0}, {30, 0})); // from the side
    EXPECT_FALSE(rayCast(world, {0, 0}, {0, 10}));   // from inside
}

TEST(RayCastAll, EveryBodyOnceByFractionThenCreationOrder) {
    World world{WorldDef{}};
    BodyId c = world.createBody(wall(50, 0, 5, 5));  // entered at x = 45
    BodyId a = world.createBody(wall(10, 0, 5, 5));  // at x = 5
    BodyId b = world.createBody(wall(30, 0, 5, 5));  // at x = 25
    BodyId b2 = world.createBody(wall(30, 3, 5, 5)); // also at x = 25: after b
    world.createBody(wall(30, 20, 5, 5));            // off the ray
    std::vector<RayHit> hits = rayCastAll(world, {0, 0}, {100, 0});
    ASSERT_EQ(hits.size(), 4u);
    EXPECT_EQ(hits[0].body, a);
    EXPECT_EQ(hits[0].fraction, 0.05f);
    EXPECT_EQ(hits[1].body, b);
    EXPECT_EQ(hits[2].body, b2);
    EXPECT_EQ(hits[3].body, c);
    EXPECT_EQ(hits[3].point, (Vec2{45, 0}));
    std::vector<RayHit> filtered = rayCastAll(world, {0, 0}, {100, 0}, {.ignore = b});
    ASSERT_EQ(filtered.size(), 3u);
    EXPECT_EQ(filtered[1].body, b2);
}

TEST(RayCast, LineOfSightThroughALongLevel) {
    // 400 tiles in a diagonal staircase, and a ray along the diagonal just above it: long
    // enough to be looked up in pieces.
    World world{WorldDef{}};
    for (int i = 0; i < 400; ++i)
        world.createBody(wall(float(i) * 16.0f + 8.0f, float(i) * 16.0f + 8.0f, 8, 8));
    // Tile i covers [16i, 16i + 16] on both axes. The line y = x + 16 would graze their
    // corners; y = x + 17 passes them all.
    EXPECT_FALSE(rayCast(world, {0, 17}, {6400, 6417}));
    // Across the staircase through (3200, 3200), the corner tiles 199 and 200 share: it
    // grazes both there, at fraction 0.5; 199 was created first.
    std::optional<RayHit> hit = rayCast(world, {0, 6400}, {6400, 0});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->body, world.bodies()[199]);
    EXPECT_EQ(hit->fraction, 0.5f);
}

// --- boxCast -----------------------------------------------------------------------------

/// A floor whose top is y = 0, and the default slop (0.01): the contact skin of a box of
/// half extent 5 against it is 2 × 0.01 × 5 = 0.1.
struct Floor {
    World world{WorldDef{}};
    BodyId floor = world.createBody(wall(0, 10, 100, 10));
};

TEST(BoxCast, StopsTouchingTheFaceItRunsInto) {
    Floor s;
    // Bottom at -15, floor top at 0: 15 of 40.
    std::optional<BoxCastHit> hit = boxCast(s.world, {0, -20}, {5, 5}, {0, 40});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->body, s.floor);
    EXPECT_EQ(hit->fraction, 0.375f);
    EXPECT_EQ(hit->normal, (Vec2{0, -1}));
    EXPECT_EQ(hit->centre, (Vec2{0, -5}));
    // Diagonally: the same time, further along x.
    hit = boxCast(s.world, {0, -20}, {5, 5}, {8, 40});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->fraction, 0.375f);
    EXPECT_EQ(hit->centre, (Vec2{3, -5}));
}

TEST(BoxCast, EndingWithinTheSkinOfAFaceStopsAtTheFace) {
    Floor s;
    // Would end 0.05 deep: stops at the face, at 15 of 15.05.
    std::optional<BoxCastHit> hit = boxCast(s.world, {0, -20}, {5, 5}, {0, 15.05f});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->centre, (Vec2{0, -5}));
    EXPECT_FALSE(boxCast(s.world, {0, -20}, {5, 5}, {0, 14.9f})); // falls short
}

TEST(BoxCast, TouchingIsNotRunningInto) {
    Floor s;
    // Resting exactly on the floor: sideways is free, down is stopped at once.
    EXPECT_FALSE(boxCast(s.world, {0, -5}, {5, 5}, {50, 0}));
    EXPECT_FALSE(boxCast(s.world, {0, -5}, {5, 5}, {50, -3})); // and up, away from it
    std::optional<BoxCastHit> hit = boxCast(s.world, {0, -5}, {5, 5}, {50, 10});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->fraction, 0.0f);
    EXPECT_EQ(hit->normal, (Vec2{0, -1}));
    EXPECT_EQ(hit->centre, (Vec2{0, -5}));
    // Sunk 0.05 into it, within the skin of 0.1, as the physical model leaves a resting
    // box: the same.
    EXPECT_FALSE(boxCast(s.world, {0, -4.95f}, {5, 5}, {50, 0}));
    hit = boxCast(s.world, {0, -4.95f}, {5, 5}, {0, 1});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->fraction, 0.0f);
    EXPECT_EQ(hit->centre, (Vec2{0, -4.95f})); // not moved back out: a cast moves forward
}

TEST(BoxCast, ABoxInsideABodyIsFreeToLeave) {
    Floor s;
    // 10 deep: more than the skin on both axes.
    EXPECT_FALSE(boxCast(s.world, {0, 5}, {5, 5}, {0, 10}));
    EXPECT_FALSE(boxCast(s.world, {0, 5}, {5, 5}, {0, -30}));
    EXPECT_EQ(queryBox(s.world, {0, 5}, {5, 5}), (std::vector<BodyId>{s.floor}));
}

TEST(BoxCast, ZeroTranslationHitsNothing) {
    Floor s;
    EXPECT_FALSE(boxCast(s.world, {0, -5}, {5, 5}, {0, 0}));
}

TEST(BoxCast, FiltersAndSensors) {
    Floor s;
    BodyId zone = s.world.createBody({.type = BodyType::Static,
                                      .x = 0,
                                      .y = -30,
                                      .hw = 10,
                                      .hh = 5,
                                      .sensor = true}); // y in [-35, -25]
    std::optional<BoxCastHit> hit = boxCast(s.world, {0, -50}, {5, 5}, {0, 100});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->body, s.floor);
    hit = boxCast(s.world, {0, -50}, {5, 5}, {0, 100}, {.includeSensors = true});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->body, zone);
    EXPECT_EQ(hit->fraction, 0.1f); // bottom -45 to -35: 10 of 100
    EXPECT_FALSE(boxCast(s.world, {0, -50}, {5, 5}, {0, 100}, {.ignore = s.floor}));
}

TEST(BoxCast, OneWayPlatformsStopOnlyWhatComesFromTheirSide) {
    World world{WorldDef{}};
    BodyId ledge = world.createBody(
        {.type = BodyType::Static, .x = 0, .y = 0, .hw = 20, .hh = 2, .oneWay = {0, -1}});
    // From above: bottom -5 to the top face -2, 3 of 10.
    std::optional<BoxCastHit> hit = boxCast(world, {0, -10}, {5, 5}, {0, 10});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->body, ledge);
    EXPECT_EQ(hit->centre, (Vec2{0, -7}));
    EXPECT_FALSE(boxCast(world, {0, 10}, {5, 5}, {0, -20}));   // from below
    EXPECT_FALSE(boxCast(world, {-40, 0}, {5, 5}, {40, 0}));   // from the side
    EXPECT_FALSE(boxCast(world, {0, -4}, {5, 5}, {0, 10}));    // partly inside: falls through
    EXPECT_TRUE(boxCast(world, {0, -6.97f}, {5, 5}, {0, 10})); // 0.03 deep, skin 0.04: lands
}

TEST(BoxCast, EqualTimesGoToTheBodyCreatedFirst) {
    World world{WorldDef{}};
    BodyId right = world.createBody(wall(10, 10, 10, 10));
    BodyId left = world.createBody(wall(-10, 10, 10, 10));
    std::optional<BoxCastHit> hit = boxCast(world, {0, -20}, {5, 5}, {0, 40});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->body, right);
    (void)left;
}

// --- moveAndSlide ------------------------------------------------------------------------

TEST(MoveAndSlide, FreeMotionGoesAllTheWay) {
    Floor s;
    MoveResult moved = moveAndSlide(s.world, {0, -50}, {5, 5}, {30, -20});
    EXPECT_EQ(moved.centre, (Vec2{30, -70}));
    EXPECT_TRUE(moved.hits.empty());
}

TEST(MoveAndSlide, LandsAndSlidesAlongTheFloor) {
    Floor s;
    // Falls 15 of 40 (t = 0.375) to touch the floor at x = 7.5, then the rest of x, 12.5.
    MoveResult moved = moveAndSlide(s.world, {0, -20}, {5, 5}, {20, 40});
    EXPECT_EQ(moved.centre, (Vec2{20, -5}));
    ASSERT_EQ(moved.hits.size(), 1u);
    EXPECT_EQ(moved.hits[0].body, s.floor);
    EXPECT_EQ(moved.hits[0].normal, (Vec2{0, -1}));
}

TEST(MoveAndSlide, ACharacterWalkingOnAFloorOfTilesNeverCatchesOnASeam) {
    // Tiles 16 wide, top at y = 0; a character of half extents (6, 12) walks right with
    // gravity pulling it into the floor each frame.
    World world{WorldDef{}};
    for (int i = 0; i < 20; ++i)
        world.createBody(wall(float(i) * 16.0f + 8.0f, 8, 8, 8));
    Vec2 centre{10, -12};
    for (int frame = 0; frame < 60; ++frame) {
        MoveResult moved = moveAndSlide(world, centre, {6, 12}, {3, 2});
        ASSERT_FALSE(moved.hits.empty());
        EXPECT_EQ(moved.hits[0].normal, (Vec2{0, -1})); // grounded, every frame
        centre = moved.centre;
    }
    EXPECT_EQ(centre, (Vec2{190, -12})); // 60 × 3 along, not a bit lower
}

TEST(MoveAndSlide, ClimbingAlongAWallOfSeparateBoxesNeverCatches) {
    World world{WorldDef{}};
    for (int i = 0; i < 10; ++i) // x in [10, 30], stacked upwards from y = 0
        world.createBody(wall(20, -float(i) * 20.0f - 10.0f, 10, 10));
    // Touching the wall (right edge at x = 10), pushing into it while going up.
    MoveResult moved = moveAndSlide(world, {5, -5}, {5, 5}, {5, -150});
    EXPECT_EQ(moved.centre, (Vec2{5, -155}));
    ASSERT_EQ(moved.hits.size(), 1u);
    EXPECT_EQ(moved.hits[0].normal, (Vec2{-1, 0}));
}

TEST(MoveAndSlide, StopsInACornerAfterTwoHits) {
    Floor s;
    BodyId wallBody = s.world.createBody(wall(20, -20, 10, 20)); // x >= 10, on the floor
    // Lands at t = 15/40 at (-5, -5); slides 25 right and meets the wall after 10.
    MoveResult moved = moveAndSlide(s.world, {-20, -20}, {5, 5}, {40, 40});
    EXPECT_EQ(moved.centre, (Vec2{5, -5}));
    ASSERT_EQ(moved.hits.size(), 2u);
    EXPECT_EQ(moved.hits[0].body, s.floor);
    EXPECT_EQ(moved.hits[0].normal, (Vec2{0, -1}));
    EXPECT_EQ(moved.hits[1].body, wallBody);
    EXPECT_EQ(moved.hits[1].normal, (Vec2{-1, 0}));
}

TEST(MoveAndSlide, LandingOnASeamReportsBothTiles) {
    World world{WorldDef{}};
    BodyId left = world.createBody(wall(-10, 10, 10, 10));
    BodyId right = world.createBody(wall(10, 10, 10, 10));
    MoveResult moved = moveAndSlide(world, {0, -20}, {5, 5}, {0, 40});
    EXPECT_EQ(moved.centre, (Vec2{0, -5}));
    ASSERT_EQ(moved.hits.size(), 2u);
    EXPECT_EQ(moved.hits[0].body, left);
    EXPECT_EQ(moved.hits[1].body, right);
}

TEST(MoveAndSlide, SensorsNeverStopIt) {
    Floor s;
    s.world.createBody(
        {.type = BodyType::Static, .x = 0, .y = -30, .hw = 10, .hh = 5, .sensor = true});
    MoveResult moved = moveAndSlide(s.world, {0, -50}, {5, 5}, {0, 100}, {.includeSensors = true});
    EXPECT_EQ(moved.centre, (Vec2{0, -5}));
    ASSERT_EQ(moved.hits.size(), 1u);
    EXPECT_EQ(moved.hits[0].body, s.floor);
}

TEST(MoveAndSlide, AKinematicCharacterIgnoresItsOwnBody) {
    Floor s;
    BodyId player =
        s.world.createBody({.type = BodyType::Kinematic, .x = 0, .y = -20, .hw = 5, .hh = 5});
    const Vec2 half = s.world.halfExtents(player);
    MoveResult moved =
        moveAndSlide(s.world, s.world.position(player), half, {0, 40}, {.ignore = player});
    s.world.setPosition(player, moved.centre);
    EXPECT_EQ(s.world.position(player), (Vec2{0, -5}));
}

// --- Agreement with brute force on random worlds -----------------------------------------

/// Floats from std::mt19937's raw bits, the same on every standard library.
class Random {
public:
    explicit Random(std::uint32_t seed) : engine_(seed) {}
    float unit() { return float(engine_() >> 8) * 0x1p-24f; }
    float uniform(float low, float high) { return low + (high - low) * unit(); }
    /// A whole number in [low, high], as a float: whole-number worlds make touching
    /// faces, grazed corners and equal fractions common.
    float whole(int low, int high) {
        return float(low + int(engine_() % std::uint32_t(high - low + 1)));
    }

private:
    std::mt19937 engine_;
};

/// The first fraction along from → to at which the point is in the closed box, by the
/// rules of rayCast, written independently of the library: the segment's parameter
/// range within each axis's slab, intersected. nullopt if none.
std::optional<float> referenceFraction(Vec2 from, Vec2 to, Vec2 lo, Vec2 hi) {
    const Vec2 d = to - from;
    if (d.x == 0 && d.y == 0)
        return std::nullopt;
    float first = -std::numeric_limits<float>::infinity();
    float last = std::numeric_limits<float>::infinity();
    const float p[2] = {from.x, from.y}, v[2] = {d.x, d.y}, a[2] = {lo.x, lo.y},
                b[2] = {hi.x, hi.y};
    for (int k = 0; k < 2; ++k) {
        if (v[k] == 0) {
            if (p[k] < a[k] || p[k] > b[k])
                return std::nullopt;
        } else {
            const float t1 = (a[k] - p[k]) / v[k], t2 = (b[k] - p[k]) / v[k];
            first = std::max(first, std::min(t1, t2));
            last = std::min(last, std::max(t1, t2));
        }
    }
    if (first > last || first > 1 || last <= 0)
        return std::nullopt;
    return std::max(first, 0.0f);
}

/// A world of mixed sizes: static walls, a pile asleep on a floor, and boxes flying about.
struct RandomWorld {
    World world{WorldDef{.gravity = {0, 0}}};
    Random random;

    explicit RandomWorld(std::uint32_t seed) : random(seed) {
        for (int i = 0; i < 1500; ++i) {
            const bool big = i % 50 == 0;
            world.createBody(wall(random.whole(-1000, 1000), random.whole(-1000, 1000),
                                  big ? random.whole(20, 200) : random.whole(1, 12),
                                  big ? random.whole(1, 20) : random.whole(1, 12)));
        }
        for (int i = 0; i < 100; ++i)
            world.createBody({.x = random.whole(-1000, 1000),
                              .y = random.whole(-1000, 1000),
                              .hw = random.whole(1, 10),
                              .hh = random.whole(1, 10),
                              .vx = random.uniform(-300, 300),
                              .vy = random.uniform(-300, 300),
                              .category = i % 3 == 0 ? 2u : 1u,
                              .sensor = i % 10 == 0});
        // Some of them at rest: they fall asleep.
        for (int i = 0; i < 100; ++i)
            world.createBody({.x = random.whole(-1000, 1000),
                              .y = random.whole(-1000, 1000),
                              .hw = random.whole(1, 10),
                              .hh = random.whole(1, 10)});
        for (int i = 0; i < 40; ++i)
            world.step(kDt);
    }

    Vec2 point() { return {random.whole(-1100, 1100), random.whole(-1100, 1100)}; }

    bool passes(BodyId id, const QueryFilter& filter) const {
        return (world.category(id) & filter.mask) != 0 && (filter.category & world.mask(id)) != 0 &&
               (filter.includeSensors || !world.isSensor(id)) && id != filter.ignore;
    }
};

TEST(QueryProperty, RayCastsAgreeWithBruteForce) {
    RandomWorld r(12345);
    int asleep = 0;
    for (BodyId id : r.world.bodies())
        asleep += r.world.type(id) == BodyType::Dynamic && !r.world.isAwake(id);
    ASSERT_GT(asleep, 50); // the grid holds sleepers too
    int hits = 0, ties = 0;
    for (int i = 0; i < 400; ++i) {
        const Vec2 from = r.point();
        // Every third ray along an axis: faces run along and seams run down.
        Vec2 to = r.point();
        if (i % 3 == 1)
            to.y = from.y;
        else if (i % 3 == 2)
            to.x = from.x;
        const QueryFilter filter{.mask = i % 4 == 0 ? 1u : 0xFFFFFFFFu,
                                 .includeSensors = i % 5 == 0};
        // Brute force: every body, in creation order; the first at the smallest fraction.
        std::optional<float> best;
        BodyId bestBody;
        std::vector<std::pair<float, BodyId>> all;
        for (BodyId id : r.world.bodies()) {
            if (!r.passes(id, filter))
                continue;
            const Vec2 c = r.world.position(id), h = r.world.halfExtents(id);
            if (std::optional<float> f = referenceFraction(from, to, c - h, c + h)) {
                all.push_back({*f, id});
                if (!best || *f < *best) {
                    best = f;
                    bestBody = id;
                }
            }
        }
        std::optional<RayHit> hit = rayCast(r.world, from, to, filter);
        ASSERT_EQ(hit.has_value(), best.has_value()) << "ray " << i;
        std::stable_sort(all.begin(), all.end(),
                         [](const auto& p, const auto& q) { return p.first < q.first; });
        std::vector<RayHit> got = rayCastAll(r.world, from, to, filter);
        ASSERT_EQ(got.size(), all.size()) << "ray " << i;
        for (std::size_t k = 0; k < all.size(); ++k) {
            EXPECT_EQ(got[k].fraction, all[k].first) << "ray " << i;
            EXPECT_EQ(got[k].body, all[k].second) << "ray " << i;
        }
        if (!best)
            continue;
        ++hits;
        ties += all.size() > 1 && all[1].first == all[0].first;
        EXPECT_EQ(hit->fraction, *best) << "ray " << i;
        EXPECT_EQ(hit->body, bestBody) << "ray " << i;
    }
    EXPECT_GT(hits, 200);
    EXPECT_GT(ties, 0); // the tie-break was exercised
}

TEST(QueryProperty, PointAndBoxQueriesAgreeWithBruteForce) {
    RandomWorld r(777);
    for (int i = 0; i < 300; ++i) {
        const Vec2 p = r.point();
        const Vec2 half{r.random.whole(0, 60), r.random.whole(0, 60)};
        const QueryFilter filter{.category = i % 2 == 0 ? 1u : 2u, .includeSensors = i % 3 == 0};
        std::vector<BodyId> atPoint, inBox;
        for (BodyId id : r.world.bodies()) {
            if (!r.passes(id, filter))
                continue;
            const Vec2 c = r.world.position(id), h = r.world.halfExtents(id);
            if (std::abs(p.x - c.x) <= h.x && std::abs(p.y - c.y) <= h.y)
                atPoint.push_back(id);
            if (std::abs(p.x - c.x) < h.x + half.x && std::abs(p.y - c.y) < h.y + half.y)
                inBox.push_back(id);
        }
        EXPECT_EQ(queryPoint(r.world, p, filter), atPoint) << i;
        EXPECT_EQ(queryBox(r.world, p, half, filter), inBox) << i;
    }
}

TEST(QueryProperty, BoxCastsStopBeforeEveryBodyInTheWay) {
    RandomWorld r(4242);
    int stopped = 0;
    for (int i = 0; i < 300; ++i) {
        const Vec2 half{r.random.whole(1, 8), r.random.whole(1, 8)};
        const Vec2 from = r.point();
        Vec2 motion = r.point() - from;
        if (i % 3 == 1)
            motion.y = 0;
        std::optional<BoxCastHit> hit = boxCast(r.world, from, half, motion);
        const float reached = hit ? hit->fraction : 1.0f;
        if (hit) {
            ++stopped;
            // It stops touching what it hit.
            const Vec2 c = r.world.position(hit->body), h = r.world.halfExtents(hit->body);
            const Vec2 gap{std::abs(hit->centre.x - c.x) - h.x - half.x,
                           std::abs(hit->centre.y - c.y) - h.y - half.y};
            EXPECT_LE(std::max(gap.x, gap.y), 1e-3f) << i;
            EXPECT_GE(std::max(gap.x, gap.y), -0.2f) << i; // within the skin at most
        }
        // Brute force: no body of the world is entered (overlapped deeper than the skin on
        // both axes, having not been at the start) before that fraction, sampled finely.
        for (BodyId id : r.world.bodies()) {
            if (r.world.isSensor(id))
                continue;
            const Vec2 c = r.world.position(id), h = r.world.halfExtents(id);
            const Vec2 skin{0.02f * std::min(half.x, h.x), 0.02f * std::min(half.y, h.y)};
            auto deep = [&](Vec2 at) {
                return std::abs(at.x - c.x) < h.x + half.x - skin.x - 1e-3f &&
                       std::abs(at.y - c.y) < h.y + half.y - skin.y - 1e-3f;
            };
            if (deep(from))
                continue; // inside at the start: free to leave
            for (int k = 0; k <= 64; ++k) {
                const float t = reached * float(k) / 64.0f;
                ASSERT_FALSE(deep(from + motion * t)) << "cast " << i << " enters a body";
            }
        }
    }
    EXPECT_GT(stopped, 100);
}

} // namespace
} // namespace jostle
