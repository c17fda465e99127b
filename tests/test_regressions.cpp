// Bugs the fuzzers found (tests/fuzz), each as the smallest case that shows it. The input
// that found it is kept in tests/fuzz/corpus/, named after it.
#include "jostle/query.hpp"
#include "jostle/tilemap.hpp"
#include "jostle/world.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace jostle {
namespace {

// Found by fuzz_api (corpus/api/classic-ccd-sweep-meets-destroyed-body). In the classic
// model with ccd, a body's sweep hit a floor whose pre-solve destroyed it; the rest of the
// sweep met the destroyed floor again and handed it to the callback, which was then given
// a stale handle in the middle of the step it was promised to be left out of.
TEST(Regressions, ClassicSweepLeavesOutABodyDestroyedByThePreSolve) {
    World world(WorldDef{.solver = Solver::Classic, .classic = {.ccd = true}});
    BodyId floor =
        world.createBody({.type = BodyType::Static, .x = 0, .y = 10, .hw = 100, .hh = 1});
    // 20 units a step at 1/60 s: the sweep meets the floor 8 units into the step.
    BodyId box = world.createBody({.x = 0, .y = 0, .hw = 1, .hh = 1, .vy = 1200});
    int calls = 0;
    world.setPreSolve([&](Collision& c) {
        ++calls;
        EXPECT_TRUE(world.isValid(c.a));
        EXPECT_TRUE(world.isValid(c.b));
        if (world.isValid(floor))
            world.destroyBody(floor);
        return true;
    });
    world.step(1.0f / 60.0f);
    EXPECT_EQ(calls, 1);
    // The floor is gone, so nothing stopped the box: it made its whole move.
    EXPECT_FLOAT_EQ(world.position(box).y, 20.0f);
}

// Found by fuzz_api with JOSTLE_FUZZ_OPEN=float-range (tests/fuzz/corpus/api/
// density-mass-overflow-unchecked). checkBodyDef refused a density x area that
// overflows, but multiplied in another order than the mass the solver uses: with a thin,
// very dense body the check's product was finite and the mass infinite.
TEST(Regressions, TheDensityMassThatIsCheckedIsTheOneUsed) {
    // density × 4 overflows first: the mass density × 4 × hw × hh is infinite, however
    // small hw × hh is.
    const BodyDef def{.hw = 1e-30f, .hh = 50.5f, .density = 3e38f};
    EXPECT_TRUE(checkBodyDef(def).has_value());
    World world;
    EXPECT_THROW(world.createBody(def), Error);
    EXPECT_EQ(world.bodyCount(), 0u);
}

// Found by fuzz_api with JOSTLE_FUZZ_OPEN=float-range (tests/fuzz/corpus/api/
// setter-density-mass-overflow). createBody refuses a body whose density × area
// overflows, but setHalfExtents and setDensity made one: a dynamic body of infinite
// mass, which the solver treats as immovable and divides by.
TEST(Regressions, SettersRefuseAnInfiniteDensityMassAsCreateBodyDoes) {
    World world;
    BodyId box = world.createBody({.hw = 10, .hh = 10});
    EXPECT_THROW(world.setHalfExtents(box, {1e20f, 1e20f}), Error);
    EXPECT_EQ(world.halfExtents(box), (Vec2{10, 10}));
    EXPECT_THROW(world.setDensity(box, 3e38f), Error);
    EXPECT_EQ(world.mass(box), 400.0f);
    // With an explicit mass, the size does not matter to the mass.
    world.setMass(box, 2);
    world.setHalfExtents(box, {1e9f, 1e9f});
    EXPECT_EQ(world.mass(box), 2.0f);
}

// Found by fuzz_api (tests/fuzz/corpus/api/contact-begin-names-destroyed-body). In the
// physical model, a pre-solve that destroyed a body whose contact of this step was
// already made left that contact in place: the step reported it as begun, under the
// handle the body's storage slot will give its next body, neither the destroyed body's
// nor a live one's.
TEST(Regressions, ABodyDestroyedByThePreSolveBeginsNoContact) {
    for (bool victimFirst : {false, true}) {
        World world(WorldDef{.gravity = {0, 800}});
        world.createBody({.type = BodyType::Static, .x = 0, .y = 10, .hw = 100, .hh = 10});
        // Both boxes land on the floor in this step; one of them is destroyed when the
        // callback sees the other's contact, before or after its own contact is made.
        BodyId victim, other;
        if (victimFirst) {
            victim = world.createBody({.x = -20, .y = -1, .hw = 1, .hh = 1, .vy = 100});
            other = world.createBody({.x = 20, .y = -1, .hw = 1, .hh = 1, .vy = 100});
        } else {
            other = world.createBody({.x = 20, .y = -1, .hw = 1, .hh = 1, .vy = 100});
            victim = world.createBody({.x = -20, .y = -1, .hw = 1, .hh = 1, .vy = 100});
        }
        world.setPreSolve([&](Collision& c) {
            if ((c.a == other || c.b == other) && world.isValid(victim))
                world.destroyBody(victim);
            return true;
        });
        world.step(1.0f / 60.0f);
        ASSERT_FALSE(world.isValid(victim));
        ASSERT_EQ(world.contactBegins().size(), 1u) << "victim first: " << victimFirst;
        EXPECT_TRUE(world.contactBegins()[0].a == other || world.contactBegins()[0].b == other);
        for (const ContactEvent& e : world.contactBegins())
            EXPECT_TRUE(world.isValid(e.a) && world.isValid(e.b))
                << "victim first: " << victimFirst;
    }
}

// Found by fuzz_api (tests/fuzz/corpus/api/classic-contact-begin-names-destroyed-body).
// The same in the classic model, where a pair is recorded as it is resolved: a body
// resolved against the floor and then destroyed by the pre-solve of a later pair was
// reported as beginning a contact, under its stale handle, and as ending it one step
// later.
TEST(Regressions, ClassicBodyDestroyedByThePreSolveBeginsNoContact) {
    World world(WorldDef{.gravity = {0, 800}, .solver = Solver::Classic});
    world.createBody({.type = BodyType::Static, .x = 0, .y = 10, .hw = 100, .hh = 10});
    // The victim comes first in creation order, so it is resolved first.
    BodyId victim = world.createBody({.x = -20, .y = -0.5f, .hw = 1, .hh = 1, .vy = 100});
    BodyId other = world.createBody({.x = 20, .y = -0.5f, .hw = 1, .hh = 1, .vy = 100});
    world.setPreSolve([&](Collision& c) {
        if (c.a == other && world.isValid(victim))
            world.destroyBody(victim);
        return true;
    });
    world.step(1.0f / 60.0f);
    ASSERT_FALSE(world.isValid(victim));
    ASSERT_EQ(world.contactBegins().size(), 1u);
    EXPECT_EQ(world.contactBegins()[0].b, other);
    world.step(1.0f / 60.0f);
    EXPECT_TRUE(world.contactEnds().empty());
}

// Found by fuzz_scene (tests/fuzz/corpus/scene/static-body-with-velocity). checkBodyDef,
// which promises nothing for a definition createBody accepts, passed a static body with a
// velocity, which createBody refuses: a scene file with one loaded, and addBodies, which
// checks every body with checkBodyDef before it creates any, threw halfway through,
// leaving the world half filled.
TEST(Regressions, CheckBodyDefRefusesAMovingStaticBodyAsCreateBodyDoes) {
    const BodyDef moving{.type = BodyType::Static, .hw = 1, .hh = 1, .vy = 1};
    ASSERT_TRUE(checkBodyDef(moving).has_value());
    EXPECT_EQ(checkBodyDef(moving)->field, "vy");
    World world;
    EXPECT_THROW(world.createBody(moving), Error);
    EXPECT_FALSE(checkBodyDef({.type = BodyType::Kinematic, .hw = 1, .hh = 1, .vy = 1}));
}

// Found by fuzz_api (tests/fuzz/corpus/api/edge-of-the-world-after-a-callback-throws).
// A body that reaches the edge of the world (math.hpp: ±1e9) stops there at the end of
// the step; a step that a pre-solve callback ended with an exception skipped that, and
// left the body beyond the edge, out of the range every function promises. (The classic
// model calls the callback after a body has moved; the physical one, before.)
TEST(Regressions, ABodyStopsAtTheEdgeOfTheWorldEvenWhenTheStepThrows) {
    World world(WorldDef{.solver = Solver::Classic});
    // 1e9 units a second carries the box 1.7e7 units past the edge in a step, into a
    // static body that reaches beyond it (its numbers are in the range, its far side is
    // not); the collision calls the callback, which throws.
    const BodyId box = world.createBody({.y = 1e9f - 10, .hw = 1, .hh = 1, .vy = 1e9f});
    world.createBody({.type = BodyType::Static, .y = 1e9f, .hw = 10, .hh = 1e8f});
    world.setPreSolve([](Collision&) -> bool { throw std::runtime_error("game over"); });
    EXPECT_THROW(world.step(1.0f / 60.0f), std::runtime_error);
    EXPECT_LE(world.position(box).y, kMaxMagnitude);
    EXPECT_LE(world.velocity(box).y, kMaxMagnitude);
}

// Found by fuzz_api (tests/fuzz/corpus/api/tile-too-small-for-its-position).
// checkTileMapDef, which promises nothing for a map createTileMap accepts, passed a tile
// of 2e-9 (the smallest, math.hpp) at x = 136: createTileMap works a box's edges out in
// double, and there they round to a half extent just below 1e-9, which createBody refused
// halfway through building the map, leaving a map without a handle. Far from the origin
// (x = 9.9e8) a tile of 1e-8 rounds to no size at all.
TEST(Regressions, ATileMapThatChecksBuilds) {
    const float tiles[] = {1.99999994e-9f, 2e-9f, 1e-8f, 1e-6f};
    const float places[] = {0, 135.925842f, 1e6f, 9.9e8f, -9.9e8f};
    for (float tile : tiles) {
        for (float x : places) {
            TileMapDef def;
            def.x = x;
            def.y = 188.981445f;
            def.tile = tile;
            def.rows = {"#.#", "###", ".#.", "#.."};
            if (checkTileMapDef(def))
                continue;
            World world;
            EXPECT_NO_THROW(createTileMap(world, def)) << "tile " << tile << " at x " << x;
        }
    }
}

// Found by fuzz_api (tests/fuzz/corpus/api/edge-of-the-world-asleep). The edge of the
// world left sleeping bodies alone, but a body can fall asleep in the very step that
// carries it past the edge: slow enough to be at rest, with a dt long enough (up to 1e9 s)
// to take it there. It stayed beyond the edge, asleep.
TEST(Regressions, ABodyThatFallsAsleepPastTheEdgeStopsAtIt) {
    World world; // sleeping is on
    // 1.5 units a second is rest for a box of half extent 40 (0.05 × 40 = 2 per second).
    const BodyId box = world.createBody({.hw = 40, .hh = 40, .vx = 1.5f});
    world.step(1e9f);
    EXPECT_LE(world.position(box).x, kMaxMagnitude);
    // Where it stopped, the queries find it.
    EXPECT_EQ(queryPoint(world, world.position(box)).size(), 1u);
}

// Found by fuzz_api (tests/fuzz/corpus/api/classic-presolve-beyond-the-edge). The
// classic model calls the pre-solve as it resolves each body, after moving it; the edge
// of the world stopped bodies only at the end of the step, so the callback saw a body
// beyond it, and a query at its position threw out of the step.
TEST(Regressions, TheClassicPreSolveSeesNoBodyBeyondTheEdge) {
    for (const bool ccd : {false, true}) {
        World world(
            WorldDef{.gravity = {0, 0}, .solver = Solver::Classic, .classic = {.ccd = ccd}});
        // A floor reaching past the edge of the world, its top at y = 15, and a box 5
        // above it, falling 10 units a step, and going right at the largest speed: 1.7e7
        // units in the step, far past the edge, where it stops, on the floor.
        world.createBody({.type = BodyType::Static,
                          .x = kMaxMagnitude,
                          .y = 1015,
                          .hw = kMaxMagnitude,
                          .hh = 1000});
        world.createBody({.x = kMaxMagnitude - 3000,
                          .y = 0,
                          .hw = 10,
                          .hh = 10,
                          .vx = kMaxMagnitude,
                          .vy = 600});
        int calls = 0;
        world.setPreSolve([&](Collision& c) {
            ++calls;
            EXPECT_TRUE(inRange(world.position(c.a)));
            EXPECT_TRUE(inRange(world.position(c.b)));
            EXPECT_NO_THROW(queryBox(world, world.position(c.a), {10, 10}));
            return true;
        });
        world.step(1.0f / 60.0f);
        EXPECT_GE(calls, 1) << "ccd " << ccd;
    }
}

} // namespace
} // namespace jostle
