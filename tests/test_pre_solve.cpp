// The pre-solve callback (docs/events.md): what it may do in the middle of a step, in both
// models (create and destroy bodies of every type, set tiles, move bodies), each case the
// smallest that showed a defect an attack (issues 19 and 28) or the fuzzers (tests/fuzz, the
// input kept in tests/fuzz/corpus/ under the name given) found.
#include "jostle/query.hpp"
#include "jostle/tilemap.hpp"
#include "jostle/world.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace jostle {
namespace {

constexpr float kDt = 1.0f / 60.0f;

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

INSTANTIATE_TEST_SUITE_P(PreSolve, EitherModel,
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

INSTANTIATE_TEST_SUITE_P(PreSolve, MadeWhileOneSleeps,
                         ::testing::Values(Maker::StaticBox, Maker::Circle, Maker::SolidTile));

// Found by fuzz_api (corpus/api/classic-ccd-sweep-meets-destroyed-body). In the classic
// model with ccd, a body's sweep hit a floor whose pre-solve destroyed it; the rest of the
// sweep met the destroyed floor again and handed it to the callback, which was then given
// a stale handle in the middle of the step it was promised to be left out of.
TEST(PreSolve, ClassicSweepLeavesOutABodyDestroyedByThePreSolve) {
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

// Found by fuzz_api (tests/fuzz/corpus/api/contact-begin-names-destroyed-body). In the
// physical model, a pre-solve that destroyed a body whose contact of this step was
// already made left that contact in place: the step reported it as begun, under the
// handle the body's storage slot will give its next body, neither the destroyed body's
// nor a live one's.
TEST(PreSolve, ABodyDestroyedByThePreSolveBeginsNoContact) {
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
TEST(PreSolve, ClassicBodyDestroyedByThePreSolveBeginsNoContact) {
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

// Found by fuzz_api (tests/fuzz/corpus/api/classic-presolve-beyond-the-edge). The
// classic model calls the pre-solve as it resolves each body, after moving it; the edge
// of the world stopped bodies only at the end of the step, so the callback saw a body
// beyond it, and a query at its position threw out of the step.
TEST(PreSolve, TheClassicPreSolveSeesNoBodyBeyondTheEdge) {
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

// Found by fuzz_api (tests/fuzz/corpus/api/firm-footing-in-pre-solve-1): a character stands
// firm on a floor as steep as its floorAngle whatever the friction (it walks there as on
// level ground). The pre-solve callback was given that footing as the pair's friction
// (1000, outside the documented [0, 1]) and clamped it to 1 on return even when it changed
// nothing, so a callback that only returned true made the character slide down a 55-degree
// floor (tan 55 > 1). The callback now sees the pair's mixed friction, and the footing
// stays firm unless it lowers the friction.
TEST(PreSolve, ACallbackThatChangesNothingLeavesACharacterFirmOnASteepFloor) {
    const float theta = 55.0f * std::numbers::pi_v<float> / 180.0f;
    const Vec2 normal{-std::sin(theta), -std::cos(theta)}; // the floor's, y down
    auto slid = [&](bool callback, float setFriction) {
        World world(WorldDef{.gravity = {0, 800}});
        world.createBody({.type = BodyType::Static,
                          .hw = 100,
                          .hh = 100 * std::tan(theta),
                          .friction = 0.5f,
                          .slope = {-1, -1}});
        // On the slope's line y = -x tan(theta), 40 up it, its low corner touching.
        const Vec2 onLine = Vec2{std::cos(theta), -std::sin(theta)} * 40.0f;
        const float reach = std::abs(normal.x) * 4 + std::abs(normal.y) * 8;
        const Vec2 centre = onLine + normal * reach;
        const BodyId player = world.createBody(
            {.x = centre.x, .y = centre.y, .hw = 4, .hh = 8, .friction = 0.5f, .character = true});
        float seen = -1.0f;
        if (callback)
            world.setPreSolve([&](Collision& c) {
                seen = c.friction;
                if (!std::isnan(setFriction))
                    c.friction = setFriction;
                return true;
            });
        for (int step = 0; step < 120; ++step)
            world.step(kDt);
        if (callback) {
            EXPECT_EQ(seen, 0.5f); // the pair's friction as the world mixes it
        }
        return length(world.position(player) - centre);
    };
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_LT(slid(false, nan), 0.1f);
    EXPECT_LT(slid(true, nan), 0.1f);
    EXPECT_LT(slid(true, 0.5f), 0.1f);  // set to what it was: no change
    EXPECT_LT(slid(true, 0.9f), 0.1f);  // more grip: still firm
    EXPECT_GT(slid(true, 0.0f), 10.0f); // on ice it slides
}

} // namespace
} // namespace jostle
